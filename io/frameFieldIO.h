#pragma once
/// @file
/// Frame fields (the exemplar's axes at every output voxel) as .vdb files.

#include <string>

#include "common/FrameField.h"

namespace solidtex {

/// Reads a user field from a .vdb with Vec3SGrids "axis_x", "axis_y", "axis_z" (each voxel's three
/// axes, the columns), sampled at every voxel of `dims` (voxel (i,j,k) = index coordinate (i,j,k));
/// inactive voxels take the grid's background. Each frame is made a rotation: its axes are normalised,
/// a left-handed frame has its exemplar z axis negated, and the nearest rotation is taken (polar
/// decomposition). A degenerate frame (an axis shorter than 1e-6, or axes parallel or coplanar: smallest
/// singular value of the normalised axes below 1e-3) throws InputError naming the voxel (the first in
/// index order). Missing or mistyped grids, or an unreadable file: InputError, one line.
FrameField readFrameField(const std::string& path, const Dims& dims);

/// Writes a field in the same format, every voxel active, voxel size 1 (for tests, and for users to
/// start from a built-in one). Throws InputError when the path cannot be written.
void writeFrameField(const std::string& path, const FrameField& field);

}  // namespace solidtex
