#include "synthesis/detail/upsample.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "common/Random.h"

namespace solidtex::synthesis::detail {

WorkVolume randomVolume(int n, const RgbImage& exemplar, std::uint64_t seed) {
  WorkVolume v;
  v.n = n;
  v.rgb.resize(v.count() * 3);
  v.source.resize(v.count());
  const std::uint64_t pixels = std::uint64_t(exemplar.pixelCount());
  tbb::parallel_for(std::size_t(0), v.count(), [&](std::size_t i) {
    Rng rng(deriveSeed(seed, i));
    v.source[i] = std::int32_t(uniformIndex(rng, pixels));
  });
  colorsFromSources(v, exemplar);
  return v;
}

void colorsFromSources(WorkVolume& volume, const RgbImage& exemplar) {
  volume.rgb.resize(volume.count() * 3);
  tbb::parallel_for(std::size_t(0), volume.count(), [&](std::size_t i) {
    const float* e = exemplar.data.data() + 3 * std::size_t(volume.source[i]);
    std::copy(e, e + 3, volume.at(i));
  });
}

WorkVolume upsampleSources(const WorkVolume& coarse, int coarseExemplarWidth, const RgbImage& fine) {
  WorkVolume v;
  v.n = 2 * coarse.n;
  v.source.resize(v.count());
  const int n = v.n;
  tbb::parallel_for(0, n, [&](int z) {
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const std::int32_t p = coarse.source[coarse.index(x / 2, y / 2, z / 2)];
        const int px = std::min(2 * (p % coarseExemplarWidth) + (x & 1), fine.width - 1);
        const int py = std::min(2 * (p / coarseExemplarWidth) + (y & 1), fine.height - 1);
        v.source[v.index(x, y, z)] = py * fine.width + px;
      }
  });
  colorsFromSources(v, fine);
  return v;
}

WorkVolume upsampleColors(const WorkVolume& coarse) {
  WorkVolume v;
  v.n = 2 * coarse.n;
  v.rgb.resize(v.count() * 3);
  const int n = v.n;
  tbb::parallel_for(0, n, [&](int z) {
    auto split = [&](int c, int& i0, float& f) {
      const float t = 0.5f * float(c) - 0.25f;
      const float fl = std::floor(t);
      i0 = int(fl);
      f = t - fl;
    };
    int z0, y0, x0;
    float fz, fy, fx;
    split(z, z0, fz);
    for (int y = 0; y < n; ++y) {
      split(y, y0, fy);
      for (int x = 0; x < n; ++x) {
        split(x, x0, fx);
        float acc[3] = {0, 0, 0};
        for (int dz = 0; dz < 2; ++dz)
          for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
              const float w = (dz ? fz : 1 - fz) * (dy ? fy : 1 - fy) * (dx ? fx : 1 - fx);
              const float* c =
                  coarse.at(coarse.index(coarse.wrap(x0 + dx), coarse.wrap(y0 + dy), coarse.wrap(z0 + dz)));
              for (int k = 0; k < 3; ++k) acc[k] += w * c[k];
            }
        std::copy(acc, acc + 3, v.at(v.index(x, y, z)));
      }
    }
  });
  return v;
}

}  // namespace solidtex::synthesis::detail
