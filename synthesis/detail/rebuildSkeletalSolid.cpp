#include "synthesis/detail/rebuildSkeletalSolid.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "synthesis/detail/SliceNeighborhoods.h"

namespace solidtex::synthesis::detail {
namespace {

// Adds slice `k` orthogonal to `axis`, rebuilt, to the 2^levels fine slices it covers.
void addRebuiltSlice(const WorkVolume& coarse, const HaarPyramid& pyramid, int axis, int k,
                     WorkVolume& fine) {
  const SliceAxes s = sliceAxes(axis);
  const int n = coarse.n;
  RgbImage slice{n, n, std::vector<float>(std::size_t(n) * n * 3)};
  std::vector<std::int32_t> sources(std::size_t(n) * n);
  std::array<int, 3> c{};
  c[axis] = k;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      c[s.u] = i, c[s.w] = j;
      const std::size_t v = coarse.index(c[0], c[1], c[2]);
      std::copy_n(coarse.at(v), 3, slice.at(i, j));
      sources[std::size_t(j) * n + i] = coarse.source[v];
    }
  const RgbImage rebuilt = rebuildFromSources(slice, sources, pyramid);
  const int repeat = fine.n / n;
  std::array<int, 3> f{};
  for (int t = 0; t < repeat; ++t) {
    f[axis] = k * repeat + t;
    for (int j = 0; j < fine.n; ++j)
      for (int i = 0; i < fine.n; ++i) {
        f[s.u] = i, f[s.w] = j;
        float* out = fine.at(fine.index(f[0], f[1], f[2]));
        const float* in = rebuilt.at(i, j);
        for (int ch = 0; ch < 3; ++ch) out[ch] += in[ch];
      }
  }
}

}  // namespace

WorkVolume rebuildSkeletalSolid(const WorkVolume& coarse, const HaarPyramid& pyramid) {
  WorkVolume fine;
  fine.n = coarse.n << pyramid.details.size();
  fine.rgb.assign(fine.count() * 3, 0.0f);
  // Directions one after another, so that every voxel sums them in the same order; the slices of one
  // direction fill disjoint voxels.
  for (int axis = 0; axis < 3; ++axis)
    tbb::parallel_for(0, coarse.n, [&](int k) { addRebuiltSlice(coarse, pyramid, axis, k, fine); });
  // Each direction adds its own detail to the voxel's colour a. Their mean would keep a third of
  // their variance where the three are unrelated, which blurs every slice; their sum over sqrt(3)
  // keeps it: v = a + (sum_d rebuilt_d - 3a) / sqrt(3).
  const float gain = 1.0f / std::sqrt(3.0f);
  const int shift = int(pyramid.details.size());
  tbb::parallel_for(0, fine.n, [&](int z) {
    for (int y = 0; y < fine.n; ++y)
      for (int x = 0; x < fine.n; ++x) {
        const float* a = coarse.at(coarse.index(x >> shift, y >> shift, z >> shift));
        float* v = fine.at(fine.index(x, y, z));
        for (int c = 0; c < 3; ++c) v[c] = std::clamp(a[c] + gain * (v[c] - 3.0f * a[c]), 0.0f, 1.0f);
      }
  });
  return fine;
}

}  // namespace solidtex::synthesis::detail
