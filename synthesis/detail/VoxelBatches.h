#pragma once
#include <array>

#include <tbb/parallel_for.h>

namespace solidtex::synthesis::detail {

/// Number of interleaved voxel batches: one per coordinate parity (x&1, y&1, z&1).
inline constexpr int kParityBatches = 8;

/// Calls f(voxel, linearIndex) for every voxel of an n^3 volume in parity batch `batch`, in
/// parallel over z-slices. Each call must only write its own voxel.
template <class F>
void forEachVoxelInBatch(int n, int batch, F&& f) {
  const int bx = batch & 1, by = (batch >> 1) & 1, bz = (batch >> 2) & 1;
  const int slices = (n - bz + 1) / 2;
  tbb::parallel_for(tbb::blocked_range<int>(0, slices, 1), [&](const tbb::blocked_range<int>& r) {
    for (int s = r.begin(); s != r.end(); ++s) {
      const int z = bz + 2 * s;
      for (int y = by; y < n; y += 2)
        for (int x = bx; x < n; x += 2) f(std::array<int, 3>{x, y, z}, (std::size_t(z) * n + y) * n + x);
    }
  });
}

/// The same voxels in a fixed sequential order (for histogram bookkeeping).
template <class F>
void forEachVoxelInBatchSequential(int n, int batch, F&& f) {
  const int bx = batch & 1, by = (batch >> 1) & 1, bz = (batch >> 2) & 1;
  for (int z = bz; z < n; z += 2)
    for (int y = by; y < n; y += 2)
      for (int x = bx; x < n; x += 2) f(std::array<int, 3>{x, y, z}, (std::size_t(z) * n + y) * n + x);
}

}  // namespace solidtex::synthesis::detail
