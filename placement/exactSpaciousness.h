#pragma once
#include <cstdint>
#include <vector>

#include "common/Grid.h"

namespace solidtex {

/// The exact spaciousness of every voxel of an id volume (0 = free): the distance from its centre to
/// the nearest occupied voxel centre or wall layer (index -1 or N on an axis), 0 at occupied voxels,
/// capped at maxRadius. The reference the SpaciousnessField kinds are measured against: a k-d tree
/// (nanoflann) of the occupied voxels that have a free face neighbour, which always hold the nearest.
/// In a periodic volume (a 3D torus) there are no walls and distances wrap around: the tree also
/// holds those voxels' images across the faces within maxRadius of the volume.
std::vector<float> exactSpaciousness(const Dims& dims, const std::vector<std::int32_t>& ids, float maxRadius,
                                     bool periodic = false);

}  // namespace solidtex
