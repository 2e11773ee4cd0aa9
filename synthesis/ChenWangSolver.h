#pragma once
#include <cstdint>
#include <vector>

#include "synthesis/ExemplarNeighborhoods.h"
#include "synthesis/RgbImage.h"
#include "synthesis/SliceMatches.h"
#include "synthesis/WorkVolume.h"

namespace solidtex::synthesis {

/// Settings of the discrete solver.
struct DiscreteSolveSettings {
  double irlsExponent = 0.8;  ///< r in w = ||s - e||^(r-2) (Kopf et al.'s robust IRLS weights)
  double irlsEpsilon = 1e-4;  ///< per component, added to squared distances before the power
  /// Histogram counts H and theta are multiplied by this before eq. 4 (1 = the paper's counts).
  double histogramScale = 1.0;
  /// How the copied pixel is chosen among the proposals: the one nearest to their weighted average
  /// (Han et al.'s discrete solver as the paper describes it), or the pixel with the largest summed
  /// weight (a weighted vote, which lets the re-weighting act on the choice itself).
  /// ColourMode: the proposal whose colour gathers the largest weight within a Gaussian colour kernel
  /// (a weighted vote robust to grain).
  enum class Choice { NearestToAverage, LargestVote, ColourMode } choice = Choice::NearestToAverage;
  double modeBandwidth = 0.01;  ///< ColourMode kernel: exp(-||a - b||^2 / bandwidth), sRGB units
};

/// Chen–Wang optimisation phase (section 4.2, discrete solver of Han et al.): every voxel computes
/// the weighted average (eq. 2) of the exemplar pixels e_{u,i,v} proposed by the slice neighbourhoods
/// covering it, with IRLS weights re-weighted by the position histogram (eq. 4), then copies the
/// proposed pixel whose colour is nearest to that average (colour and source position).
/// `positionHistogram` (voxels per exemplar pixel) is kept in step with volume.source; `theta` is
/// the expected count per pixel. Voxels are updated in 8 parity batches, the histogram refreshed in
/// between. Deterministic for any thread count.
void discreteSolve(WorkVolume& volume, const RgbImage& exemplar, const ExemplarNeighborhoods& neighborhoods, const SliceMatches& matches,
                   const std::vector<double>& theta, std::vector<std::int64_t>& positionHistogram,
                   const DiscreteSolveSettings& settings = {});

/// Counts how many voxels copy each exemplar pixel (`pixels` bins).
std::vector<std::int64_t> positionHistogramOf(const std::vector<std::int32_t>& source, int pixels);

} // namespace solidtex::synthesis
