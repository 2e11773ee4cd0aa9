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

/// How many neighbourhoods lie within minSeparation of one (itself included): the most a set skips.
int separationWindow(int minSeparation) {
  const int side = 2 * std::max(0, minSeparation) + 1;
  return side * side;
}

/// Fills every set from `knn(first, count, query, ids, distances)`, which writes the `query`
/// nearest neighbourhoods (by distance, then id) of neighbourhoods first..first+count-1.
template <class Knn>
SimilaritySets fillSets(const ExemplarNeighborhoods& n, int k, int minSeparation, Knn&& knn) {
  const int count = n.count();
  SimilaritySets sets;
  sets.k = std::clamp(k, 1, std::max(1, count));
  sets.ids.assign(std::size_t(count) * sets.k, 0);
  const int query = std::min(count, sets.k + separationWindow(minSeparation));
  constexpr int batch = 16384;  // bounds the candidate lists' memory on large exemplars
  std::vector<std::int32_t> ids(std::size_t(std::min(count, batch)) * query);
  std::vector<float> distances(ids.size());
  for (int first = 0; first < count; first += batch) {
    const int last = std::min(count, first + batch);
    knn(first, last - first, query, ids.data(), distances.data());
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
  return sets;
}

}  // namespace

SimilaritySets buildSimilaritySets(const ExemplarNeighborhoods& n, int k, int minSeparation) {
  if (n.count() == 0) return SimilaritySets{1, {}};
  const KdTree tree(n.reduced.data(), n.count(), n.reducedDims());
  return fillSets(
      n, k, minSeparation, [&](int first, int count, int query, std::int32_t* ids, float* distances) {
        tbb::parallel_for(tbb::blocked_range<int>(0, count, 64), [&](const tbb::blocked_range<int>& r) {
          for (int i = r.begin(); i != r.end(); ++i)
            tree.knn(n.reducedAt(first + i), query, ids + std::size_t(i) * query,
                     distances + std::size_t(i) * query);
        });
      });
}

SimilaritySets buildApproximateSimilaritySets(const ExemplarNeighborhoods& n, int k, int minSeparation,
                                              const InvertedFileOptions& options) {
  if (n.count() == 0) return SimilaritySets{1, {}};
  const InvertedFileIndex index(n.reduced.data(), n.count(), n.reducedDims(), options);
  const int query = std::min(n.count(), std::clamp(k, 1, n.count()) + separationWindow(minSeparation));
  std::vector<std::int32_t> allIds(std::size_t(n.count()) * query);
  std::vector<float> allDistances(allIds.size());
  index.knnOfAllPoints(query, allIds.data(), allDistances.data());
  SimilaritySets sets =
      fillSets(n, k, minSeparation, [&](int first, int count, int q, std::int32_t* ids, float* distances) {
        const std::size_t from = std::size_t(first) * q, size = std::size_t(count) * q;
        std::copy_n(allIds.begin() + from, size, ids);
        std::copy_n(allDistances.begin() + from, size, distances);
      });
  sets.lists = index.lists();
  sets.probes = index.probes();
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
