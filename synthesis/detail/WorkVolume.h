#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace solidtex::synthesis::detail {

/// The volume being synthesised at one level: a periodic n^3 cube, x fastest.
struct WorkVolume {
  int n = 0;
  std::vector<float> rgb;            ///< n^3 * 3, sRGB in [0,1]
  std::vector<std::int32_t> source;  ///< n^3 exemplar pixel index (y * width + x) each voxel copies, or empty

  std::size_t count() const { return std::size_t(n) * n * n; }
  std::size_t index(int x, int y, int z) const { return (std::size_t(z) * n + y) * n + x; }
  /// Periodic wrap of one coordinate into [0, n).
  int wrap(int v) const {
    v %= n;
    return v < 0 ? v + n : v;
  }
  const float* at(std::size_t i) const { return rgb.data() + 3 * i; }
  float* at(std::size_t i) { return rgb.data() + 3 * i; }
};

}  // namespace solidtex::synthesis::detail
