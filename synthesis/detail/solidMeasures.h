#pragma once
#include <cstdint>
#include <vector>

#include "synthesis/SynthesisOptions.h"
#include "synthesis/detail/RgbImage.h"
#include "synthesis/detail/WorkVolume.h"
#include "voxel/SolidVolume.h"

namespace solidtex::synthesis {

/// Slice energy, Kopf's and Chen and Wang's eq. 1: the mean over sampled slice neighbourhoods of
/// ||s - e||^gamma, e the nearest exemplar neighbourhood (exact, full dimension), gamma = kEnergyExponent,
/// the distance taken per component (RMS over the vector, colours sRGB in [0,1]) so that sizes compare. The
/// squared form (gamma = 2: the mean squared distance per component) is kept beside it: it weighs a few bad
/// seams far more than many near-exact copies, so it prefers a blend to copies.
struct SliceEnergy {
  double axis = 0;         ///< on slices orthogonal to x, y and z
  double oblique = 0;      ///< on randomly rotated planes (trilinear sampling, periodic)
  double axisSquared = 0;  ///< the same neighbourhoods, gamma = 2
  double obliqueSquared = 0;
};

/// Measures the slice energy of a periodic sRGB volume against the exemplar. Deterministic.
SliceEnergy sliceEnergy(const WorkVolume& srgbVolume, const RgbImage& exemplar,
                        const SliceMeasureOptions& options = {});

/// Total-variation distance (in [0,1]) between the joint RGB histograms (bins^3) of `count`
/// interleaved sRGB colours and of the exemplar's pixels.
double colorHistogramDistance(const float* rgb, std::size_t count, const RgbImage& exemplar, int bins = 8);

/// Statistics of the position histogram (voxels per exemplar pixel).
struct PositionHistogramStats {
  double coverage = 0;   ///< share of exemplar pixels copied by at least one voxel
  double flatness = 0;   ///< normalised entropy of the histogram: 1 = every pixel equally often
  double variation = 0;  ///< coefficient of variation (std / mean) of the counts
};

/// Statistics of the sources (exemplar pixel index per voxel, negative = none) over `pixels` pixels.
PositionHistogramStats positionHistogramStats(const std::vector<std::int32_t>& sources, int pixels);

/// A periodic sRGB working volume from a (cubic) SolidVolume's linear colours, sources kept when
/// present (exemplar pixel index y * exemplarWidth + x).
WorkVolume srgbVolumeOf(const SolidVolume& volume, int exemplarWidth);

}  // namespace solidtex::synthesis
