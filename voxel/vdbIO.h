#pragma once
#include <string>

#include "voxel/SolidVolume.h"

namespace solidtex {

/// Writes the volume to a .vdb (voxel (i,j,k) centred at world (i,j,k) * voxelSize). Writes to a
/// temporary name beside `path` and renames, so no partial file is ever left. Throws InputError
/// when the path cannot be written. Takes the volume by value: move a large one in, and its dense
/// arrays are freed grid by grid as the .vdb's trees are built.
void writeVdb(const std::string& path, SolidVolume volume, double voxelSize = 1.0);

/// Reads a .vdb written by writeVdb (or any file with a `density` FloatGrid; `color` optional) into
/// dense form over the active bounding box of its grids, starting at index 0.
SolidVolume readVdb(const std::string& path);

}  // namespace solidtex
