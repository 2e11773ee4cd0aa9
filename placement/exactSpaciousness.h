#pragma once
#include <cstdint>
#include <vector>

#include "common/Grid.h"

namespace solidtex {

/// The exact spaciousness of every voxel of an id volume (0 = free): the distance from its centre to
/// the nearest occupied voxel centre or wall layer (index -1 or N on an axis), 0 at occupied voxels,
/// capped at maxRadius. The reference the SpaciousnessField kinds are measured against: a k-d tree
/// (nanoflann) of the occupied voxels that have a free face neighbour, which always hold the nearest.
std::vector<float> exactSpaciousness(const Dims& dims, const std::vector<std::int32_t>& ids, float maxRadius);

}  // namespace solidtex
