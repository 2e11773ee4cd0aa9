#pragma once
#include <vector>

#include "common/SolidVolume.h"
#include "io/detail/vdbGrids.h"

namespace solidtex::io::detail {

// The grids writeVdb writes for `volume`, in groups made when the writer reaches them, each
// consuming its dense arrays. Voxel (i, j, k) lies at index origin + (i, j, k), centred at world
// index x voxelSize. `volume` must outlive the groups.
std::vector<GridGroupMaker> gridGroupsOf(SolidVolume& volume, double voxelSize);

}  // namespace solidtex::io::detail
