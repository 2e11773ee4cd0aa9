#pragma once
#include <cstdint>
#include <vector>

#include "synthesis/SynthesisOptions.h"
#include "synthesis/detail/ExemplarNeighborhoods.h"
#include "synthesis/detail/RgbImage.h"
#include "synthesis/detail/SliceMatches.h"
#include "synthesis/detail/WorkVolume.h"
#include "synthesis/detail/histograms.h"

namespace solidtex::synthesis::detail {

/// Settings of the discrete solver.
struct DiscreteSolveSettings {
  double irlsExponent = kEnergyExponent;  ///< r in w = ||s - e||^(r-2) (Kopf et al.'s robust IRLS weights)
  double irlsEpsilon = 1e-4;              ///< per component, added to squared distances before the power
  /// Histogram counts H and theta are multiplied by this before eq. 4 (1 = the paper's counts).
  double histogramScale = 1.0;
  ProposalChoice choice = ProposalChoice::ColorMode;
  double modeBandwidth = 0.01;  ///< ColorMode kernel: exp(-||a - b||^2 / bandwidth), sRGB units
};

/// The global statistics the discrete solver re-weights with and keeps in step with the volume.
struct DiscreteHistograms {
  const std::vector<double>* theta = nullptr;     ///< expected voxels per exemplar pixel (eq. 4)
  std::vector<std::int64_t>* position = nullptr;  ///< voxels copying each exemplar pixel
  /// Per-channel colour histograms of the exemplar and of the volume for eq. 3, or null for none.
  /// Eq. 4 alone only penalises single over-used pixels: when a whole colour class is under-used
  /// while the majority class still has unused pixels (two flat colours, thin veins), nothing stops
  /// the class from eroding. Eq. 3 sees the class.
  const ChannelHistograms* exemplarColors = nullptr;
  ChannelHistograms* volumeColors = nullptr;
};

/// Chen–Wang optimisation phase (section 4.2, discrete solver of Han et al.): every voxel weighs
/// the exemplar pixels e_{u,i,v} proposed by the slice neighbourhoods covering it, with IRLS
/// weights re-weighted by the position histogram (eq. 4) and, when given, the colour histograms
/// (eq. 3), then copies one proposed pixel (colour and source position) as settings.choice says.
/// The histograms are kept in step with volume.source. Voxels are updated in 8 parity batches, the
/// histograms refreshed in between. Deterministic for any thread count.
void discreteSolve(WorkVolume& volume, const RgbImage& exemplar, const ExemplarNeighborhoods& neighborhoods,
                   const SliceMatches& matches, const DiscreteHistograms& histograms,
                   const DiscreteSolveSettings& settings = {});

/// Counts how many voxels copy each exemplar pixel (`pixels` bins).
std::vector<std::int64_t> positionHistogramOf(const std::vector<std::int32_t>& source, int pixels);

}  // namespace solidtex::synthesis::detail
