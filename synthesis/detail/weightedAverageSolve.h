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

/// Settings of Kopf et al.'s least-squares (IRLS) solver.
struct WeightedAverageSettings {
  double irlsExponent = kEnergyExponent;  ///< r in w = ||s - e||^(r-2)
  double irlsEpsilon = 1e-4;              ///< per component, added to squared distances before the power
};

/// Kopf et al. 2007 optimisation phase (Chen–Wang eq. 2 with eq. 3): every voxel becomes the
/// weighted average of the exemplar pixels proposed by the slice neighbourhoods covering it, IRLS
/// weights divided by the per-channel colour histogram excess (eq. 3). `volumeHistogram` is kept in
/// step with volume.rgb (8 parity batches, refreshed in between). volume.source receives the
/// proposal with the largest weight (the dominant source, for statistics only). Deterministic.
void weightedAverageSolve(WorkVolume& volume, const RgbImage& exemplar,
                          const ExemplarNeighborhoods& neighborhoods, const SliceMatches& matches,
                          const ChannelHistograms& exemplarHistogram, ChannelHistograms& volumeHistogram,
                          const WeightedAverageSettings& settings = {});

}  // namespace solidtex::synthesis::detail
