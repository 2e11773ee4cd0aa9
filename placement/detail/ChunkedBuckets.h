#pragma once
// Internal: many growing lists of voxel indices, stored in chunks from one shared pool.
#include <cstddef>
#include <memory>
#include <vector>

#include "placement/detail/voxelSets.h"

namespace solidtex::placement::detail {

/// The buckets of a BucketQueue: lists of voxel indices kept in chunks of kChunk entries that come
/// from, and go back to, one pool. Growing vectors would each keep room they do not use, and the
/// memory their reallocations free stays with the C library, scattered between live blocks: with
/// about an entry per voxel in all, that doubled what the lists hold. Entry i of a bucket is found
/// in O(1), and a bucket holds ceil(size / kChunk) chunks.
class ChunkedBuckets {
public:
  static constexpr std::size_t kChunk = 1024;  // a 4 KiB page of entries

  class Bucket {
  public:
    std::size_t size() const { return size_; }
    VoxelIndex& operator[](std::size_t i) { return chunks_[i / kChunk][i % kChunk]; }
    VoxelIndex operator[](std::size_t i) const { return chunks_[i / kChunk][i % kChunk]; }
    VoxelIndex back() const { return (*this)[size_ - 1]; }

  private:
    friend class ChunkedBuckets;
    std::vector<VoxelIndex*> chunks_;
    std::size_t size_ = 0;
  };

  explicit ChunkedBuckets(std::size_t count) : buckets_(count) {}

  std::size_t size() const { return buckets_.size(); }
  Bucket& operator[](std::size_t k) { return buckets_[k]; }
  const Bucket& operator[](std::size_t k) const { return buckets_[k]; }

  void push(std::size_t k, VoxelIndex v) {
    Bucket& bucket = buckets_[k];
    if (bucket.size_ == bucket.chunks_.size() * kChunk) bucket.chunks_.push_back(takeChunk());
    bucket.chunks_.back()[bucket.size_ % kChunk] = v;
    ++bucket.size_;
  }

  void popBack(std::size_t k) {
    Bucket& bucket = buckets_[k];
    if (--bucket.size_ % kChunk == 0) dropLastChunk(bucket);
  }

  /// Keeps the entries of bucket k that `keep` accepts, in their order.
  template <class Keep>
  void filter(std::size_t k, Keep&& keep) {
    Bucket& bucket = buckets_[k];
    std::size_t kept = 0;
    for (std::size_t i = 0; i < bucket.size_; ++i)
      if (const VoxelIndex v = bucket[i]; keep(v)) bucket[kept++] = v;
    bucket.size_ = kept;
    while (bucket.chunks_.size() * kChunk >= kept + kChunk) dropLastChunk(bucket);
  }

  void clear(std::size_t k) {
    filter(k, [](VoxelIndex) { return false; });
  }

  /// Heap bytes held: every chunk ever made (the pool keeps those given back) and the chunk lists.
  std::size_t bytes() const {
    std::size_t total = pool_.capacity() * sizeof(pool_[0]) + free_.capacity() * sizeof(VoxelIndex*) +
                        pool_.size() * kChunk * sizeof(VoxelIndex);
    for (const Bucket& bucket : buckets_)
      total += sizeof(Bucket) + bucket.chunks_.capacity() * sizeof(VoxelIndex*);
    return total;
  }

private:
  VoxelIndex* takeChunk() {
    if (free_.empty()) {
      pool_.push_back(std::make_unique_for_overwrite<VoxelIndex[]>(kChunk));
      return pool_.back().get();
    }
    VoxelIndex* chunk = free_.back();
    free_.pop_back();
    return chunk;
  }

  void dropLastChunk(Bucket& bucket) {
    free_.push_back(bucket.chunks_.back());
    bucket.chunks_.pop_back();
  }

  std::vector<Bucket> buckets_;
  std::vector<std::unique_ptr<VoxelIndex[]>> pool_;
  std::vector<VoxelIndex*> free_;
};

}  // namespace solidtex::placement::detail
