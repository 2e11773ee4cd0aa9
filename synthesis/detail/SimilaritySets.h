#pragma once
#include <cstdint>
#include <vector>

#include "synthesis/detail/ExemplarNeighborhoods.h"
#include "synthesis/detail/InvertedFileIndex.h"

namespace solidtex::synthesis::detail {

/// k-coherence similarity sets (Tong et al. 2002): for every exemplar neighbourhood m, the
/// neighbourhood itself followed by its k-1 nearest others in PCA space, sorted by increasing
/// distance (ties: smaller id first). Neighbourhoods whose centres lie within `minSeparation`
/// pixels (Chebyshev) of m's centre are skipped so a set does not fill with one-pixel shifts.
struct SimilaritySets {
  int k = 0;
  std::vector<std::int32_t> ids;  ///< count * k; set of m at m*k
  int lists = 0;                  ///< approximate sets: the inverted file's cells; 0 for exact sets
  int probes = 0;                 ///< approximate sets: cells searched per neighbourhood

  const std::int32_t* of(int m) const { return ids.data() + std::size_t(m) * k; }
  int count() const { return k ? int(ids.size() / std::size_t(k)) : 0; }
};

/// Builds the sets with an exact kd-tree (nanoflann), queries in parallel (TBB); deterministic.
/// k is clamped to the number of neighbourhoods.
SimilaritySets buildSimilaritySets(const ExemplarNeighborhoods& neighborhoods, int k, int minSeparation = 0);

/// The same sets from an approximate index (InvertedFileIndex): a neighbour in a cell that is not
/// probed can be missed, and a nearer one of the probed cells takes its place. For large exemplars
/// (hundreds of thousands of neighbourhoods), where the exact search takes minutes. Deterministic.
SimilaritySets buildApproximateSimilaritySets(const ExemplarNeighborhoods& neighborhoods, int k,
                                              int minSeparation = 0, const InvertedFileOptions& options = {});

/// The same sets by exhaustive search (reference for tests; O(M^2)).
SimilaritySets bruteForceSimilaritySets(const ExemplarNeighborhoods& neighborhoods, int k,
                                        int minSeparation = 0);

}  // namespace solidtex::synthesis::detail
