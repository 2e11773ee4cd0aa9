#pragma once
// Internal: uniform draws over the live entries of bucketed candidate spots.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "common/Random.h"

namespace solidtex::placement::detail {

/// Draws entries uniformly (with replacement) from buckets [first, buckets.size()) and hands each to
/// `take`, which returns false for a stale entry (skipped: uniform over the live ones). Stops after
/// `count` taken or 4 * count draws, so a bucket set that is mostly stale cannot stall it.
template <class Buckets, class Take>
void sampleUniformly(const Buckets& buckets, std::size_t first, std::size_t count, Rng& rng, Take&& take) {
  std::vector<std::size_t> ends;  // cumulative entry counts from bucket `first` on
  std::size_t total = 0;
  for (std::size_t k = first; k < buckets.size(); ++k) ends.push_back(total += buckets[k].size());
  if (total == 0) return;
  std::size_t taken = 0;
  for (std::size_t draw = 0; draw < 4 * count && taken < count; ++draw) {
    const std::size_t i = std::size_t(uniformIndex(rng, total));
    const std::size_t b = std::size_t(std::upper_bound(ends.begin(), ends.end(), i) - ends.begin());
    const auto& bucket = buckets[first + b];
    taken += take(bucket[i - (ends[b] - bucket.size())]) ? 1 : 0;
  }
}

}  // namespace solidtex::placement::detail
