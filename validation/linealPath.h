#pragma once
#include <array>
#include <vector>

#include "validation/PhaseField.h"

namespace solidtex {

/// The lineal path function L(r) of a phase along each axis, r = 0..maxDistance voxels: the
/// probability that a segment from a voxel to the one r further along the axis lies wholly in the
/// phase (L(0) = phi), over the segments that fit in the field. Empty for an axis the field is flat in.
std::array<std::vector<double>, 3> linealPath(const PhaseField& phase, int maxDistance);

}  // namespace solidtex
