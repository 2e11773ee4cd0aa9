#pragma once
#include <string>

#include "common/SolidVolume.h"

namespace solidtex {

/// Writes the volume to a .vdb (voxel (i,j,k) centred at world (i,j,k) * voxelSize), as
/// writeVdbGrids. Throws InputError when the path cannot be written. Takes the volume by value: move a large
/// one in, and its dense arrays are freed grid by grid as the .vdb's trees are built.
void writeVdb(const std::string& path, SolidVolume volume, double voxelSize = 1.0);

/// Which of a .vdb's grids readVdb makes dense; the arrays of those left out stay empty. A density
/// or colour grid left out still gives the box, from the bounds its writer recorded (OpenVDB's file
/// statistics, which solidtex and OpenVDB's own writer keep), or from its tree when none were.
struct VdbReadOptions {
  bool density = true;
  /// The largest grid, 12 bytes a voxel dense and about as much as a tree: left out by measures
  /// of particle ids, so that a 1024^3 solid's fit in memory.
  bool color = true;
  bool particleId = true;
};

/// Reads a .vdb written by writeVdb (or any file with a `density` FloatGrid and/or a `color`
/// Vec3SGrid) into dense form over the active bounding box of those grids, its first voxel at
/// index 0 (a CT crop that starts elsewhere is shifted there).
SolidVolume readVdb(const std::string& path, const VdbReadOptions& options = {});

}  // namespace solidtex
