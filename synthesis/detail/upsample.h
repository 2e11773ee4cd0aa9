#pragma once
#include <cstdint>

#include "synthesis/detail/RgbImage.h"
#include "synthesis/detail/WorkVolume.h"

namespace solidtex::synthesis::detail {

/// A volume of n^3 voxels, each copying a uniformly random exemplar pixel (colour and source);
/// voxel i draws from its own stream deriveSeed(seed, i), so the result is thread-count independent.
WorkVolume randomVolume(int n, const RgbImage& exemplar, std::uint64_t seed);

/// Sets every voxel's colour to the exemplar pixel it copies.
void colorsFromSources(WorkVolume& volume, const RgbImage& exemplar);

/// Discrete upsampling (coarse level -> next finer level, twice the size): child (2x+dx, 2y+dy, 2z+dz)
/// copies pixel 2p + (dx, dy) of the finer exemplar, p its parent's source (clamped to the image).
WorkVolume upsampleSources(const WorkVolume& coarse, int coarseExemplarWidth, const RgbImage& fineExemplar);

/// Continuous upsampling: trilinear interpolation of colour on the periodic volume (voxel centres
/// at integer coordinates, child 2x+d sits at coarse coordinate x + d/2 - 1/4). No sources.
WorkVolume upsampleColors(const WorkVolume& coarse);

}  // namespace solidtex::synthesis::detail
