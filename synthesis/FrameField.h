#pragma once
#include <string>
#include <vector>

#include "common/FrameField.h"

namespace solidtex {

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

}  // namespace solidtex
