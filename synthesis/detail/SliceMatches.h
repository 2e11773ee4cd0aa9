#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "synthesis/detail/AxisExemplars.h"
#include "synthesis/detail/ExemplarNeighborhoods.h"
#include "synthesis/detail/KdTree.h"
#include "synthesis/detail/SimilaritySets.h"
#include "synthesis/detail/SliceNeighborhoods.h"
#include "synthesis/detail/WorkVolume.h"

namespace solidtex::synthesis::detail {

/// The search phase's result: for each matched slice neighbourhood (SliceCentreGrid), the nearest
/// exemplar neighbourhood e_{v,i} and the full-dimension squared distance ||s_{v,i} - e_{v,i}||^2.
struct SliceMatches {
  SliceCentreGrid grid;
  std::vector<std::int32_t> match;  ///< exemplar neighbourhood id, -1 before the first search
  std::vector<float> distance;      ///< squared distance over all shape.dims() components

  explicit SliceMatches(const SliceCentreGrid& g = {})
      : grid(g), match(g.count(), -1), distance(g.count(), 0.0f) {}
};

/// How the search phase finds each slice neighbourhood's nearest exemplar neighbourhood.
struct SearchSettings {
  const SimilaritySets* sets = nullptr;  ///< k-coherence search over the candidate set (needs volume.source)
  /// Per axis, a kd-tree over the PCA coefficients of the neighbourhoods that axis matches, its
  /// ids counted from axes->first (when no sets / not exhaustive)
  std::array<const KdTree*, 3> trees{};
  const AxisExemplars* axes = nullptr;  ///< which neighbourhoods each axis matches; null: all
  bool exhaustive = false;              ///< every exemplar neighbourhood is a candidate
  int coherenceRadius = 1;              ///< k-coherence: neighbours within this slice radius give candidates
  const std::vector<double>* phi =
      nullptr;                  ///< index-histogram matching (eq. 5-6) against these expected counts
  double histogramScale = 1.0;  ///< H and phi are multiplied by this before eq. 6 (1 = plain counts)
  double distanceFloor = 1e-4;  ///< per component, added to squared distances before eq. 5
  int batches = 4;              ///< index histogram refreshed between interleaved batches
};

/// Search phase over all centres of `matches.grid`, comparing PCA coefficients. With `phi`, the
/// distance to candidate i is weighted by eq. 6 using `indexHistogram` (counts of current matches
/// per exemplar neighbourhood), which is kept up to date. The previous match is always a candidate.
/// Returns the energy: mean over centres of the squared distance per component. Deterministic for
/// any thread count.
double searchPhase(const WorkVolume& volume, const ExemplarNeighborhoods& exemplar,
                   const SearchSettings& settings, SliceMatches& matches,
                   std::vector<std::int64_t>& indexHistogram);

}  // namespace solidtex::synthesis::detail
