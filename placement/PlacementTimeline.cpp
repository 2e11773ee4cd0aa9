#include "placement/PlacementTimeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

namespace solidtex {
namespace {

// The edge that holds this many of the largest particles across, at least kMinEdge: in smaller
// blocks the walls shape the packing and the time curve drifts from a large block's (gravel at one
// voxel per pixel: a 128^3 block's curve put 256^3's time left 1.4-3.2 times too long, 192^3's
// 1.0-1.5 times, from a fifth of the run on; docs/performance.md).
constexpr double kLargestAcross = 3;
constexpr int kMinEdge = 192;
// Timing costs at most this share of the voxels placed (and a little more time: smaller blocks
// cost more per voxel).
constexpr double kMaxVoxelShare = 1.0 / 20;

}  // namespace

PlacementTimeline::PlacementTimeline(const std::vector<std::pair<double, double>>& samples) {
  // From the first particle: a phase's start (its bins' expected volumes) costs the same in any
  // block, a larger share of a small one.
  if (samples.empty()) return;
  const double origin = samples.front().second;
  for (const auto& [filled, seconds] : samples)
    if (filled_.empty() || filled > filled_.back()) {
      filled_.push_back(filled);
      seconds_.push_back(seconds - origin);
    }
  total_ = samples.back().second - origin;  // to the end: particles in the margin fill no share
}

double PlacementTimeline::timeShare(double filled) const {
  if (filled_.empty() || filled <= filled_.front()) return 0;
  if (filled >= filled_.back() || total_ <= 0) return 1;
  const std::size_t i =
      std::size_t(std::upper_bound(filled_.begin(), filled_.end(), filled) - filled_.begin());
  const double t = (filled - filled_[i - 1]) / (filled_[i] - filled_[i - 1]);
  return std::min(1.0, (seconds_[i - 1] + t * (seconds_[i] - seconds_[i - 1])) / total_);
}

std::optional<Dims> timelineBlock(const Dims& placed, const Dims& counted, double largestSide) {
  if (counted.x > placed.x || counted.y > placed.y || counted.z > placed.z) return std::nullopt;
  const int edge = std::max(kMinEdge, int(std::ceil(kLargestAcross * largestSide)));
  const Dims block{std::min(counted.x, edge), std::min(counted.y, edge), std::min(counted.z, edge)};
  const Dims blockPlaced{block.x + placed.x - counted.x, block.y + placed.y - counted.y,
                         block.z + placed.z - counted.z};
  if (double(blockPlaced.count()) > kMaxVoxelShare * double(placed.count())) return std::nullopt;
  return block;
}

PlacementTimeline timePlacement(const ExemplarStats& stats, const ParticleFactory& factory, PlacerKind placer,
                                float radiusCap, PlacementOptions options, const Dims& block) {
  const Dims margin = options.counted ? Dims{options.dims.x - options.counted->dims().x,
                                             options.dims.y - options.counted->dims().y,
                                             options.dims.z - options.counted->dims().z}
                                      : Dims{0, 0, 0};
  options.dims = {block.x + margin.x, block.y + margin.y, block.z + margin.z};
  if (options.counted) options.counted = Box::at(options.counted->lo, block);
  std::unique_ptr<SpaciousnessField> field =
      makeSpaciousnessField(placer, options.dims, radiusCap, options.periodic);
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  std::vector<std::pair<double, double>> samples;
  options.progressEvery = 1;
  const double target = targetFraction(stats, options);
  options.progress = [&](double fraction, int) {
    samples.emplace_back(target > 0 ? fraction / target : 1,
                         std::chrono::duration<double>(Clock::now() - start).count());
  };
  placeLargestFirst(stats, factory, *field, options);
  return PlacementTimeline(samples);
}

}  // namespace solidtex
