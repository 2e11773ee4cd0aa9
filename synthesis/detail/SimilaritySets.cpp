#include "synthesis/detail/SimilaritySets.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <numeric>

#include <tbb/parallel_for.h>

#include "synthesis/detail/KdTree.h"

namespace solidtex::synthesis {

namespace {

bool tooClose(const ExemplarNeighborhoods& n, int a, int b, int minSeparation) {
  return std::abs(n.centreX(a) - n.centreX(b)) <= minSeparation &&
         std::abs(n.centreY(a) - n.centreY(b)) <= minSeparation;
}

/// Fills the set of m from candidates sorted by (distance, id): self first, then admissible others;
/// if too few are admissible, the closest inadmissible ones fill up.
void fillSet(const ExemplarNeighborhoods& n, int m, int k, int minSeparation,
             const std::vector<std::pair<float, std::int32_t>>& sorted, std::int32_t* out) {
  int filled = 0;
  out[filled++] = m;
  for (const auto& [d, id] : sorted)
    if (filled < k && id != m && !tooClose(n, m, id, minSeparation)) out[filled++] = id;
  for (const auto& [d, id] : sorted)
    if (filled < k && id != m && tooClose(n, m, id, minSeparation)) out[filled++] = id;
  while (filled < k) out[filled++] = m;
}

}  // namespace

SimilaritySets buildSimilaritySets(const ExemplarNeighborhoods& n, int k, int minSeparation) {
  const int count = n.count();
  SimilaritySets sets;
  sets.k = std::clamp(k, 1, std::max(1, count));
  sets.ids.assign(std::size_t(count) * sets.k, 0);
  if (count == 0) return sets;
  const int d = n.reducedDims();
  KdTree tree(n.reduced.data(), count, d);
  const int side = 2 * std::max(0, minSeparation) + 1;
  const int query = std::min(count, sets.k + side * side);
  tbb::parallel_for(tbb::blocked_range<int>(0, count, 64), [&](const tbb::blocked_range<int>& r) {
    std::vector<std::int32_t> ids(query);
    std::vector<float> dist(query);
    std::vector<std::pair<float, std::int32_t>> sorted;
    for (int m = r.begin(); m != r.end(); ++m) {
      tree.knn(n.reducedAt(m), query, ids.data(), dist.data());
      sorted.clear();
      for (int i = 0; i < query; ++i)
        if (ids[i] >= 0) sorted.emplace_back(dist[i], ids[i]);
      fillSet(n, m, sets.k, minSeparation, sorted, sets.ids.data() + std::size_t(m) * sets.k);
    }
  });
  return sets;
}

SimilaritySets bruteForceSimilaritySets(const ExemplarNeighborhoods& n, int k, int minSeparation) {
  const int count = n.count();
  SimilaritySets sets;
  sets.k = std::clamp(k, 1, std::max(1, count));
  sets.ids.assign(std::size_t(count) * sets.k, 0);
  const int d = n.reducedDims();
  std::vector<std::pair<float, std::int32_t>> all(count);
  for (int m = 0; m < count; ++m) {
    for (int o = 0; o < count; ++o) {
      float s = 0;
      for (int c = 0; c < d; ++c) {
        const float diff = n.reducedAt(m)[c] - n.reducedAt(o)[c];
        s += diff * diff;
      }
      all[o] = {s, o};
    }
    std::sort(all.begin(), all.end());
    fillSet(n, m, sets.k, minSeparation, all, sets.ids.data() + std::size_t(m) * sets.k);
  }
  return sets;
}

}  // namespace solidtex::synthesis
