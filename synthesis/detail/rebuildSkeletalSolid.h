#pragma once
#include "synthesis/detail/HaarPyramid.h"
#include "synthesis/detail/WorkVolume.h"

namespace solidtex::synthesis::detail {

/// Section 3 of Pan et al.: the full-resolution solid from a coarse one whose voxels record the coarse
/// exemplar pixel they copy. Every slice of each of the three directions is rebuilt in 2D
/// (rebuildFromSources, the exemplar's x and y along the slice's axes as sliceAxes says), each rebuilt
/// slice fills the 2^levels slices it covers along its axis, and the three directions are mixed: the
/// voxel's colour plus the sum of the three directions' details over sqrt(3), which keeps the
/// details' variance where the mean would divide it by three. The result has no sources: a voxel
/// mixes three. Same output for any thread count.
WorkVolume rebuildSkeletalSolid(const WorkVolume& coarse, const HaarPyramid& pyramid);

}  // namespace solidtex::synthesis::detail
