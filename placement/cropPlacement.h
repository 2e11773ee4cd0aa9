#pragma once
#include "common/Grid.h"
#include "placement/placeLargestFirst.h"

namespace solidtex {

/// The box of `dims` voxels at `lo` cut out of a placement, as a block cut out of a larger solid:
/// particles that cross its faces keep their inside voxels, particles with none inside are dropped
/// and the rest renumbered 1..P in their placing order. Per-bin counts, the volume histogram and the
/// volume fraction are those of the box; the stop reason and shrinking are kept.
PlacementResult cropPlacement(const PlacementResult& placement, const Voxel& lo, const Dims& dims);

}  // namespace solidtex
