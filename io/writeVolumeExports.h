#pragma once
/// @file
/// A volume's grids for tools other than Blender: TIFF stacks (Fiji), numpy arrays, VTK image data
/// (ParaView).

#include <optional>
#include <string>
#include <vector>

#include "common/OutputFiles.h"
#include "common/SolidVolume.h"
#include "io/writeTiffStack.h"

namespace solidtex {

/// Where a volume command writes its grids besides the .vdb (each optional).
struct VolumeExports {
  std::optional<std::string> tiff;  ///< folder: color.tif (8-bit sRGB), particle_id.tif, density.tif
  std::optional<std::string>
      npy;  ///< folder: color.npy (Z,Y,X,3 linear float32), particle_id.npy, density.npy
  std::optional<std::string> vti;  ///< one .vti file with every grid as cell data, in the .vdb's units
};

/// Declares the exports' folders and file with `outputs` (before any work).
void addVolumeExports(OutputFiles& outputs, const VolumeExports& exports);

/// Writes the volume's non-empty grids (color, particle_id, density) to every export asked for,
/// through `outputs`; returns the paths written.
std::vector<std::string> writeVolumeExports(OutputFiles& outputs, const VolumeExports& exports,
                                            const SolidVolume& volume, const VoxelSize& voxelSize);

}  // namespace solidtex
