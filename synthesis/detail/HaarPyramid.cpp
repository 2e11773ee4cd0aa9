#include "synthesis/detail/HaarPyramid.h"

#include <algorithm>
#include <stdexcept>

namespace solidtex::synthesis::detail {
namespace {

RgbImage blankImage(int width, int height) {
  return {width, height, std::vector<float>(std::size_t(width) * std::size_t(height) * 3, 0.0f)};
}

// The 2x2 block at (2x, 2y) of `out` from approximation a and details h, v, d (3 channels each).
void writeBlock(RgbImage& out, int x, int y, const float* a, const float* h, const float* v, const float* d) {
  for (int c = 0; c < 3; ++c) {
    out.at(2 * x, 2 * y)[c] = a[c] + h[c] + v[c] + d[c];
    out.at(2 * x + 1, 2 * y)[c] = a[c] - h[c] + v[c] - d[c];
    out.at(2 * x, 2 * y + 1)[c] = a[c] + h[c] - v[c] - d[c];
    out.at(2 * x + 1, 2 * y + 1)[c] = a[c] - h[c] - v[c] + d[c];
  }
}

RgbImage crop(const RgbImage& image, int width, int height) {
  RgbImage out = blankImage(width, height);
  for (int y = 0; y < height; ++y) std::copy_n(image.at(0, y), std::size_t(width) * 3, out.at(0, y));
  return out;
}

}  // namespace

HaarLevel haarForward(const RgbImage& image) {
  if (image.width % 2 != 0 || image.height % 2 != 0)
    throw std::invalid_argument("the Haar transform needs an even width and height");
  const int w = image.width / 2, h = image.height / 2;
  HaarLevel level{blankImage(w, h), {w, h, {}, {}, {}}};
  HaarDetails& out = level.details;
  const std::size_t values = std::size_t(w) * std::size_t(h) * 3;
  out.h.resize(values), out.v.resize(values), out.d.resize(values);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const float p00 = image.at(2 * x, 2 * y)[c], p10 = image.at(2 * x + 1, 2 * y)[c],
                    p01 = image.at(2 * x, 2 * y + 1)[c], p11 = image.at(2 * x + 1, 2 * y + 1)[c];
        const std::size_t i = (std::size_t(y) * w + x) * 3 + c;
        level.approximation.at(x, y)[c] = 0.25f * (p00 + p10 + p01 + p11);
        out.h[i] = 0.25f * (p00 - p10 + p01 - p11);
        out.v[i] = 0.25f * (p00 + p10 - p01 - p11);
        out.d[i] = 0.25f * (p00 - p10 - p01 + p11);
      }
  return level;
}

RgbImage haarInverse(const RgbImage& approximation, const HaarDetails& details) {
  if (approximation.width != details.width || approximation.height != details.height)
    throw std::invalid_argument("approximation and details differ in size");
  RgbImage out = blankImage(2 * approximation.width, 2 * approximation.height);
  for (int y = 0; y < approximation.height; ++y)
    for (int x = 0; x < approximation.width; ++x) {
      const std::size_t i = (std::size_t(y) * approximation.width + x) * 3;
      writeBlock(out, x, y, approximation.at(x, y), &details.h[i], &details.v[i], &details.d[i]);
    }
  return out;
}

HaarPyramid buildHaarPyramid(const RgbImage& exemplar, int levels) {
  if (levels < 1) throw std::invalid_argument("a Haar pyramid needs at least one level");
  const int multiple = 1 << levels;
  HaarPyramid p;
  p.finest = crop(exemplar, exemplar.width / multiple * multiple, exemplar.height / multiple * multiple);
  RgbImage current = p.finest;
  for (int l = 0; l < levels; ++l) {
    HaarLevel level = haarForward(current);
    p.details.push_back(std::move(level.details));
    current = std::move(level.approximation);
  }
  p.coarse = std::move(current);
  return p;
}

RgbImage rebuildFromSources(const RgbImage& image, const std::vector<std::int32_t>& sources,
                            const HaarPyramid& pyramid) {
  RgbImage current = image;
  std::vector<std::int32_t> from = sources;
  for (int l = int(pyramid.details.size()) - 1; l >= 0; --l) {
    const HaarDetails& details = pyramid.details[std::size_t(l)];
    RgbImage finer = blankImage(2 * current.width, 2 * current.height);
    std::vector<std::int32_t> finerFrom(std::size_t(finer.pixelCount()));
    for (int y = 0; y < current.height; ++y)
      for (int x = 0; x < current.width; ++x) {
        const std::int32_t s = from[std::size_t(y) * current.width + x];
        const int sx = s % details.width, sy = s / details.width;
        const std::size_t i = std::size_t(s) * 3;
        writeBlock(finer, x, y, current.at(x, y), &details.h[i], &details.v[i], &details.d[i]);
        for (int b = 0; b < 2; ++b)
          for (int a = 0; a < 2; ++a)
            finerFrom[std::size_t(2 * y + b) * finer.width + 2 * x + a] =
                (2 * sy + b) * (2 * details.width) + 2 * sx + a;
      }
    current = std::move(finer);
    from = std::move(finerFrom);
  }
  return current;
}

}  // namespace solidtex::synthesis::detail
