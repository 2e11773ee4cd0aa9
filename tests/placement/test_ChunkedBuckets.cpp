#include <gtest/gtest.h>

#include <vector>

#include "placement/detail/ChunkedBuckets.h"

namespace solidtex::placement::detail {
namespace {

constexpr std::size_t kChunk = ChunkedBuckets::kChunk;

std::vector<VoxelIndex> contents(const ChunkedBuckets::Bucket& bucket) {
  std::vector<VoxelIndex> out;
  for (std::size_t i = 0; i < bucket.size(); ++i) out.push_back(bucket[i]);
  return out;
}

// Two buckets filled across several chunk boundaries, interleaved, hold what a vector each would.
TEST(ChunkedBuckets, HoldTheirEntriesInOrderAcrossChunks) {
  ChunkedBuckets buckets(3);
  std::vector<VoxelIndex> a, b;
  for (VoxelIndex v = 0; v < 3 * kChunk + 7; ++v) {
    buckets.push(1, v);
    a.push_back(v);
    if (v % 3 == 0) {
      buckets.push(2, 10 * v);
      b.push_back(10 * v);
    }
  }
  EXPECT_EQ(contents(buckets[1]), a);
  EXPECT_EQ(contents(buckets[2]), b);
  EXPECT_EQ(buckets[0].size(), 0u);
  buckets[1][kChunk + 5] = 99;
  EXPECT_EQ(buckets[1][kChunk + 5], 99u);
  EXPECT_EQ(buckets[1].back(), a.back());
}

// Chunks emptied by pops and filters go back to the pool, and filling again reuses them: the pool
// holds only as many chunks as the buckets needed at most.
TEST(ChunkedBuckets, GiveEmptiedChunksBackForReuse) {
  ChunkedBuckets buckets(2);
  for (VoxelIndex v = 0; v < 4 * kChunk; ++v) buckets.push(1, v);
  const std::size_t full = buckets.bytes();
  for (std::size_t i = 0; i < 2 * kChunk + 1; ++i) buckets.popBack(1);
  EXPECT_EQ(buckets[1].size(), 2 * kChunk - 1);
  EXPECT_EQ(buckets[1].back(), 2 * kChunk - 2);
  buckets.filter(1, [](VoxelIndex v) { return v % 2 == 1; });  // keeps 1, 3, 5, ...
  ASSERT_EQ(buckets[1].size(), kChunk - 1);
  for (std::size_t i = 0; i < buckets[1].size(); ++i) EXPECT_EQ(buckets[1][i], 2 * i + 1);
  for (VoxelIndex v = 0; v < 3 * kChunk; ++v) buckets.push(0, v);
  const std::size_t chunk = kChunk * sizeof(VoxelIndex);
  EXPECT_LT(buckets.bytes(), full + chunk);  // four chunks in all, as before
  buckets.clear(0);
  buckets.clear(1);
  EXPECT_EQ(buckets[0].size() + buckets[1].size(), 0u);
  EXPECT_LT(buckets.bytes(), full + chunk);
}

}  // namespace
}  // namespace solidtex::placement::detail
