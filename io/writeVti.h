#pragma once
/// @file
/// Volumes as VTK XML image data (.vti), which ParaView opens (Debian's ParaView reads no .vdb).

#include <cstddef>
#include <string>
#include <vector>

#include "common/Grid.h"

namespace solidtex {

/// One per-voxel array of a .vti file: `components` values of `type` per voxel, x fastest.
struct VtiArray {
  std::string name;
  std::string type;  ///< VTK's name: "Float32", "Int32", "UInt8"
  int components = 1;
  std::size_t componentBytes = 4;
  const void* data = nullptr;
};

/// Writes the arrays as cell data of an image of `dims` cells (one per voxel) of edge `spacing`,
/// voxel (i,j,k) centred at (origin + (i,j,k)) x spacing as in the .vdb, raw-appended and little-endian,
/// checking every write. Throws InputError when the file cannot be written.
void writeVti(const std::string& path, const Dims& dims, const Voxel& origin, double spacing,
              const std::vector<VtiArray>& arrays);

}  // namespace solidtex
