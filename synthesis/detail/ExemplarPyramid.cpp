#include "synthesis/detail/ExemplarPyramid.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "common/Error.h"

namespace solidtex::synthesis::detail {

namespace {

cv::Mat toFloat(const cv::Mat& m, const char* what) {
  if (m.empty()) throw InputError(std::string(what) + " is empty");
  cv::Mat f;
  if (m.depth() == CV_8U)
    m.convertTo(f, CV_32F, 1.0 / 255.0);
  else if (m.depth() == CV_16U)
    m.convertTo(f, CV_32F, 1.0 / 65535.0);
  else if (m.depth() == CV_32F)
    f = m;
  else
    throw InputError(std::string(what) + " has an unsupported pixel type (expected 8-bit, 16-bit or float)");
  return f;
}

}  // namespace

RgbImage toRgbImage(const cv::Mat& srgb) {
  cv::Mat f = toFloat(srgb, "exemplar");
  cv::Mat rgb;
  switch (f.channels()) {
    case 1:
      cv::cvtColor(f, rgb, cv::COLOR_GRAY2RGB);
      break;
    case 3:
      rgb = f;
      break;
    case 4:
      cv::cvtColor(f, rgb, cv::COLOR_RGBA2RGB);
      break;
    default:
      throw InputError("exemplar has " + std::to_string(f.channels()) + " channels (expected 1, 3 or 4)");
  }
  RgbImage out;
  out.width = rgb.cols;
  out.height = rgb.rows;
  out.data.resize(std::size_t(out.width) * out.height * 3);
  for (int y = 0; y < out.height; ++y) {
    const float* row = rgb.ptr<float>(y);
    for (int x = 0; x < out.width * 3; ++x)
      out.data[std::size_t(y) * out.width * 3 + x] = std::clamp(row[x], 0.0f, 1.0f);
  }
  return out;
}

std::vector<float> toControlValues(const cv::Mat& control) {
  cv::Mat f = toFloat(control, "control map");
  cv::Mat grey;
  switch (f.channels()) {
    case 1:
      grey = f;
      break;
    case 3:
      cv::cvtColor(f, grey, cv::COLOR_RGB2GRAY);
      break;
    case 4:
      cv::cvtColor(f, grey, cv::COLOR_RGBA2GRAY);
      break;
    default:
      throw InputError("control map has " + std::to_string(f.channels()) + " channels (expected 1, 3 or 4)");
  }
  std::vector<float> out(std::size_t(grey.rows) * grey.cols);
  for (int y = 0; y < grey.rows; ++y)
    for (int x = 0; x < grey.cols; ++x)
      out[std::size_t(y) * grey.cols + x] = std::clamp(grey.at<float>(y, x), 0.0f, 1.0f);
  return out;
}

RgbImage halve(const RgbImage& image) {
  RgbImage out;
  out.width = image.width / 2;
  out.height = image.height / 2;
  out.data.resize(std::size_t(out.width) * out.height * 3);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 3; ++c)
        out.at(x, y)[c] = 0.25f * (image.at(2 * x, 2 * y)[c] + image.at(2 * x + 1, 2 * y)[c] +
                                   image.at(2 * x, 2 * y + 1)[c] + image.at(2 * x + 1, 2 * y + 1)[c]);
  return out;
}

namespace {

std::vector<float> halveScalar(const std::vector<float>& v, int width, int height) {
  const int w = width / 2, h = height / 2;
  std::vector<float> out(std::size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      out[std::size_t(y) * w + x] =
          0.25f * (v[std::size_t(2 * y) * width + 2 * x] + v[std::size_t(2 * y) * width + 2 * x + 1] +
                   v[std::size_t(2 * y + 1) * width + 2 * x] + v[std::size_t(2 * y + 1) * width + 2 * x + 1]);
  return out;
}

}  // namespace

ExemplarPyramid buildExemplarPyramid(const RgbImage& finest, int levels, const std::vector<float>& control) {
  ExemplarPyramid p;
  p.levels.resize(levels);
  p.control.resize(levels);
  p.levels[levels - 1] = finest;
  if (!control.empty()) {
    constexpr float floor = 0.05f;  // black still appears a little: theta(p) > 0
    auto& c = p.control[levels - 1];
    c.resize(control.size());
    for (std::size_t i = 0; i < control.size(); ++i) c[i] = floor + control[i];
  }
  for (int l = levels - 2; l >= 0; --l) {
    p.levels[l] = halve(p.levels[l + 1]);
    if (!control.empty())
      p.control[l] = halveScalar(p.control[l + 1], p.levels[l + 1].width, p.levels[l + 1].height);
  }
  return p;
}

}  // namespace solidtex::synthesis::detail
