#pragma once
/// @file PlacementTimeline.h
/// @brief How placement's time spreads over the volume it fills, timed on a smaller block.
#include <optional>
#include <utility>
#include <vector>

#include "common/Grid.h"
#include "placement/SpaciousnessField.h"
#include "placement/placeLargestFirst.h"

namespace solidtex {

/// The share of a placement's time spent by the time each share of its target volume is filled.
/// The large particles fill the volume fast and the many small ones slowly, in the same proportions
/// in any block that holds several of the largest, so a small block's curve gives a large block's
/// share of the time done (docs/performance.md, progress estimates); the filled volume alone
/// promises a fifth of the time left.
class PlacementTimeline {
public:
  /// `samples`: (share of the target volume filled, seconds since placing began), in placing order.
  explicit PlacementTimeline(const std::vector<std::pair<double, double>>& samples);
  /// The share of the time from the first particle to the last spent once `filled` of the target
  /// volume is, in [0, 1].
  double timeShare(double filled) const;

private:
  std::vector<double> filled_, seconds_;  ///< filled_ rising strictly; seconds_ since the first particle
  double total_ = 0;                      ///< seconds from the first particle to the end
};

/// Where to time a placement of `placed` voxels whose counted box is `counted`, its largest
/// particle `largestSide` voxels across: a block that holds a few of the largest, at most a
/// twentieth of the voxels placed; none when no such block is small enough, or `counted` exceeds
/// `placed`.
std::optional<Dims> timelineBlock(const Dims& placed, const Dims& counted, double largestSide);

/// Places `options`' particles in a block of `block` voxels (plus the margin `options` keeps
/// around its counted box) with a field of `placer` capped at `radiusCap`, and times it.
PlacementTimeline timePlacement(const ExemplarStats& stats, const ParticleFactory& factory, PlacerKind placer,
                                float radiusCap, PlacementOptions options, const Dims& block);

}  // namespace solidtex
