#pragma once
// Internal: per-voxel keys with one bucket of voxels per key (paper Fig. 5).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/Random.h"
#include "placement/detail/ChunkedBuckets.h"
#include "placement/detail/uniformSample.h"
#include "placement/detail/voxelSets.h"

namespace solidtex::placement::detail {

/// Every voxel has a key (0 = occupied, never queued) and sits in the bucket of its key.
/// Keys only ever decrease, so instead of doubly linked lists (8 bytes a voxel) a lowered voxel is
/// appended to its new bucket and its old entry is left behind, recognised as stale because the
/// voxel's key no longer matches. Checking stale entries one by one costs a cache miss each, so it
/// is done only in the buckets that are sampled (compacted there once they are mostly stale); the
/// rest are cleaned together, by one streaming pass over the keys, once the stale entries pass both
/// a quarter of the live ones and a sixteenth of the volume. A voxel costs sizeof(Key) + 4 bytes,
/// plus up to a quarter as much again in stale entries, and random members of a bucket are drawn in
/// O(1).
template <class Key>
class BucketQueue {
public:
  /// Queues every voxel with a non-zero key; maxKey bounds all keys.
  BucketQueue(std::vector<Key> keys, Key maxKey)
      : keys_(std::move(keys)), buckets_(std::size_t(maxKey) + 1), staleIn_(buckets_.size()) {
    rebuild();
  }

  Key key(VoxelIndex v) const { return keys_[v]; }
  const Key* keys() const { return keys_.data(); }
  std::size_t maxKey() const { return buckets_.size() - 1; }

  /// Moves v to the bucket of newKey, which must be below its key.
  void lower(VoxelIndex v, Key newKey) {
    if (keys_[v] != 0) {
      ++stale_;
      ++staleIn_[keys_[v]];
    }
    keys_[v] = newKey;
    if (newKey != 0)
      buckets_.push(newKey, v);
    else
      --live_;
    if (4 * stale_ > std::max(live_, keys_.size() / 4)) rebuild();
  }

  /// Appends up to maxCount - out.size() voxels with keys >= minKey: the smallest key first, and
  /// within a key a random sample without replacement (a partial Fisher-Yates shuffle of the bucket,
  /// whose order is otherwise irrelevant). Stale entries met on the way are dropped.
  void sample(std::size_t minKey, std::size_t maxCount, Rng& rng, std::vector<VoxelIndex>& out) {
    for (std::size_t k = std::max<std::size_t>(minKey, 1); k < buckets_.size() && out.size() < maxCount;
         ++k) {
      ChunkedBuckets::Bucket& bucket = buckets_[k];
      if (2 * staleIn_[k] > bucket.size()) compact(k);
      std::size_t taken = 0;
      while (out.size() < maxCount && taken < bucket.size()) {
        const std::size_t j = taken + std::size_t(uniformIndex(rng, bucket.size() - taken));
        if (keys_[bucket[j]] != k) {
          bucket[j] = bucket.back();
          buckets_.popBack(k);
          --stale_;
          --staleIn_[k];
          continue;
        }
        std::swap(bucket[taken], bucket[j]);
        out.push_back(bucket[taken++]);
      }
    }
  }

  /// Hands up to maxCount voxels with keys >= minKey, drawn uniformly with replacement, to `take`.
  template <class Take>
  void sampleUniformly(std::size_t minKey, std::size_t maxCount, Rng& rng, Take&& take) const {
    detail::sampleUniformly(buckets_, std::max<std::size_t>(minKey, 1), maxCount, rng, [&](VoxelIndex v) {
      if (keys_[v] == 0 || keys_[v] < minKey) return false;  // stale: lowered since
      take(v);
      return true;
    });
  }

  /// Heap bytes held (keys and buckets), for memory reports.
  std::size_t bytes() const {
    return keys_.capacity() * sizeof(Key) + staleIn_.capacity() * sizeof(std::size_t) + buckets_.bytes();
  }

private:
  void compact(std::size_t k) {
    buckets_.filter(k, [&](VoxelIndex v) { return keys_[v] == k; });
    stale_ -= staleIn_[k];
    staleIn_[k] = 0;
  }

  // Every bucket afresh from the keys, in index order.
  void rebuild() {
    for (std::size_t k = 1; k < buckets_.size(); ++k) buckets_.clear(k);
    live_ = 0;
    for (std::size_t v = 0; v < keys_.size(); ++v)
      if (keys_[v] != 0) {
        buckets_.push(keys_[v], VoxelIndex(v));
        ++live_;
      }
    stale_ = 0;
    std::fill(staleIn_.begin(), staleIn_.end(), 0);
  }

  std::vector<Key> keys_;
  ChunkedBuckets buckets_;
  std::vector<std::size_t> staleIn_;  ///< stale entries per bucket
  std::size_t live_ = 0;              ///< voxels with a non-zero key
  std::size_t stale_ = 0;             ///< bucket entries whose voxel has a lower key now
};

}  // namespace solidtex::placement::detail
