#pragma once
#include "placement/placeLargestFirst.h"

namespace solidtex {

/// A placement's counted box (PlacementOptions::counted) as a solid of its own, as a block cut out of a
/// larger solid: particles that cross its faces keep their inside voxels, particles with none inside
/// are dropped and the rest renumbered 1..P in their placing order, origins are taken to the box's.
/// Per-bin counts, the volume histogram and the volume fraction are those of the box; the stop
/// reason and shrinking are kept. Its ids already cover the box alone: they are renumbered in place.
PlacementResult cropToCountedBox(PlacementResult placement);

}  // namespace solidtex
