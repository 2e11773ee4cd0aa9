#pragma once
#include <vector>

namespace solidtex::synthesis::detail {

/// A plain float RGB image, row-major, 3 interleaved channels (R,G,B), sRGB in [0,1] unless stated.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<float> data;  ///< width * height * 3

  int pixelCount() const { return width * height; }
  const float* at(int x, int y) const { return data.data() + 3 * (std::size_t(y) * width + x); }
  float* at(int x, int y) { return data.data() + 3 * (std::size_t(y) * width + x); }
};

}  // namespace solidtex::synthesis::detail
