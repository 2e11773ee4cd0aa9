#include "synthesis/detail/SimilaritySets.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <numeric>

#include <tbb/parallel_for.h>

#include "synthesis/detail/KdTree.h"

namespace solidtex::synthesis::detail {

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

/// How many neighbourhoods lie within minSeparation of one (itself included): the most a set skips.
int separationWindow(int minSeparation) {
  const int side = 2 * std::max(0, minSeparation) + 1;
  return side * side;
}

/// Sets of the right size for `n`, not yet filled.
SimilaritySets emptySets(const ExemplarNeighborhoods& n, int k) {
  SimilaritySets sets;
  sets.k = std::clamp(k, 1, std::max(1, n.count()));
  sets.ids.assign(std::size_t(n.count()) * sets.k, 0);
  return sets;
}

/// The number of nearest neighbourhoods to look up per set: enough for k after skipping the close ones.
int queryCount(const ExemplarNeighborhoods& n, const SimilaritySets& sets, int minSeparation) {
  return std::min(n.count(), sets.k + separationWindow(minSeparation));
}

/// Fills the sets of neighbourhoods first..last-1 from rows of their `query` nearest (by distance,
/// then id; row 0 belongs to `first`).
void fillSets(const ExemplarNeighborhoods& n, int first, int last, int query, int minSeparation,
              const std::int32_t* ids, const float* distances, SimilaritySets& sets) {
  tbb::parallel_for(tbb::blocked_range<int>(first, last, 64), [&](const tbb::blocked_range<int>& r) {
    std::vector<std::pair<float, std::int32_t>> sorted;
    for (int m = r.begin(); m != r.end(); ++m) {
      const std::size_t row = std::size_t(m - first) * query;
      sorted.clear();
      for (int i = 0; i < query; ++i)
        if (ids[row + i] >= 0) sorted.emplace_back(distances[row + i], ids[row + i]);
      fillSet(n, m, sets.k, minSeparation, sorted, sets.ids.data() + std::size_t(m) * sets.k);
    }
  });
}

}  // namespace

SimilaritySets buildSimilaritySets(const ExemplarNeighborhoods& n, int k, int minSeparation) {
  SimilaritySets sets = emptySets(n, k);
  if (n.count() == 0) return sets;
  const KdTree tree(n.reduced.data(), n.count(), n.reducedDims());
  const int query = queryCount(n, sets, minSeparation);
  constexpr int batch = 16384;  // bounds the candidate lists' memory on large exemplars
  std::vector<std::int32_t> ids(std::size_t(std::min(n.count(), batch)) * query);
  std::vector<float> distances(ids.size());
  for (int first = 0; first < n.count(); first += batch) {
    const int last = std::min(n.count(), first + batch);
    tbb::parallel_for(tbb::blocked_range<int>(first, last, 64), [&](const tbb::blocked_range<int>& r) {
      for (int m = r.begin(); m != r.end(); ++m) {
        const std::size_t row = std::size_t(m - first) * query;
        tree.knn(n.reducedAt(m), query, ids.data() + row, distances.data() + row);
      }
    });
    fillSets(n, first, last, query, minSeparation, ids.data(), distances.data(), sets);
  }
  return sets;
}

SimilaritySets buildApproximateSimilaritySets(const ExemplarNeighborhoods& n, int k, int minSeparation,
                                              const InvertedFileOptions& options) {
  SimilaritySets sets = emptySets(n, k);
  if (n.count() == 0) return sets;
  const InvertedFileIndex index(n.reduced.data(), n.count(), n.reducedDims(), options);
  const int query = queryCount(n, sets, minSeparation);
  std::vector<std::int32_t> ids(std::size_t(n.count()) * query);
  std::vector<float> distances(ids.size());
  index.knnOfAllPoints(query, ids.data(), distances.data());
  fillSets(n, 0, n.count(), query, minSeparation, ids.data(), distances.data(), sets);
  sets.lists = index.lists();
  sets.probes = index.probes();
  return sets;
}

SimilaritySets bruteForceSimilaritySets(const ExemplarNeighborhoods& n, int k, int minSeparation) {
  const int count = n.count();
  SimilaritySets sets = emptySets(n, k);
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

}  // namespace solidtex::synthesis::detail
