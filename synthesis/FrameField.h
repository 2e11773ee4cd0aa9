#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

#include "common/Grid.h"

namespace solidtex {

/// Per output voxel, where each exemplar axis points in the output: column a of axes[v] is the
/// output-space direction of exemplar axis a (x, y, z). Identity everywhere = plain (isometric) synthesis.
struct FrameField {
  Dims dims;
  std::vector<Eigen::Matrix3f> axes;  ///< dims.count(), x fastest (Dims::index)

  const Eigen::Matrix3f& at(int i, int j, int k) const { return axes[dims.index(i, j, k)]; }
};

/// Built-in fields over `dims`, all rotations (orthonormal, right-handed), the same on every z slice
/// except slant3d, which is constant. The centre is c = ((dims.x - 1) / 2, (dims.y - 1) / 2) in voxel
/// coordinates, d = (i, j) - c.
/// - "circle": exemplar y radial (d / |d|), exemplar x tangential (clockwise, (d.y, -d.x) / |d|, so
///   x cross y = z), z stays z: a rotation about z by atan2(d.y, d.x) - 90 degrees. Identity at d = 0.
/// - "oval": the same around the ellipses (d.x / 2)^2 + d.y^2 = const (axis ratio 2:1, the long axis
///   along output x): exemplar y along their normal, normalise(d.x, 4 d.y), exemplar x tangent to them.
/// - "slant": a constant 45 degree turn about z: exemplar x = (1, 1, 0) / sqrt2, y = (-1, 1, 0) / sqrt2.
/// - "zigzag": a turn about z by +45 degrees or -45 degrees in bands along x, alternating every half
///   period h = max(4, round(dims.x / 8)) voxels (period 2h, about a quarter of dims.x and at least 8):
///   +45 where floor(i / h) is even. Lines along exemplar x trace a triangle wave.
/// - "slant3d": a constant 45 degree rotation about the axis (1, 1, 0) / sqrt2, tilting exemplar z out
///   of the XY plane.
/// Throws InputError for an unknown name (listing the valid ones) or a non-positive size.
FrameField builtinFrameField(const std::string& name, const Dims& dims);

/// Names of the built-in fields, for --help and errors.
const std::vector<std::string>& builtinFrameFieldNames();

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
