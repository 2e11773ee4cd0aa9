#include "common/gaussianFilter.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace solidtex {

std::vector<float> gaussianKernel(double sigma) {
  if (sigma <= 0) return {1.f};
  const int reach = std::max(1, int(std::ceil(3 * sigma)));
  std::vector<float> kernel(std::size_t(2 * reach + 1));
  double total = 0;
  for (int t = -reach; t <= reach; ++t)
    total += kernel[std::size_t(t + reach)] = float(std::exp(-t * t / (2 * sigma * sigma)));
  for (float& w : kernel) w = float(w / total);
  return kernel;
}

void correlateAlong(const float* in, float* out, const Dims& dims, int channels, int axis,
                    const std::vector<float>& kernel) {
  const int r = int(kernel.size()) / 2;
  const std::size_t c = std::size_t(channels);
  const std::size_t row = std::size_t(dims.x) * c, slice = row * std::size_t(dims.y);
  tbb::parallel_for(tbb::blocked_range<int>(0, dims.z), [&](const tbb::blocked_range<int>& ks) {
    for (int k = ks.begin(); k < ks.end(); ++k) {
      float* o = out + std::size_t(k) * slice;
      if (axis == 2) {
        std::fill(o, o + slice, 0.f);
        for (int t = -r; t <= r; ++t) {
          const float w = kernel[std::size_t(t + r)];
          const float* s = in + std::size_t(std::clamp(k + t, 0, dims.z - 1)) * slice;
          for (std::size_t v = 0; v < slice; ++v) o[v] += w * s[v];
        }
        continue;
      }
      const float* s = in + std::size_t(k) * slice;
      for (int j = 0; j < dims.y; ++j) {
        float* orow = o + std::size_t(j) * row;
        if (axis == 1) {
          std::fill(orow, orow + row, 0.f);
          for (int t = -r; t <= r; ++t) {
            const float w = kernel[std::size_t(t + r)];
            const float* srow = s + std::size_t(std::clamp(j + t, 0, dims.y - 1)) * row;
            for (std::size_t i = 0; i < row; ++i) orow[i] += w * srow[i];
          }
          continue;
        }
        const float* srow = s + std::size_t(j) * row;
        for (int i = 0; i < dims.x; ++i)
          for (std::size_t ch = 0; ch < c; ++ch) {
            float sum = 0;
            for (int t = -r; t <= r; ++t)
              sum +=
                  kernel[std::size_t(t + r)] * srow[std::size_t(std::clamp(i + t, 0, dims.x - 1)) * c + ch];
            orow[std::size_t(i) * c + ch] = sum;
          }
      }
    }
  });
}

}  // namespace solidtex
