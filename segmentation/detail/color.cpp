#include "segmentation/detail/color.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <opencv2/core.hpp>

#include "common/srgb.h"

namespace solidtex::segmentation::detail {
namespace {

// A curve on [0,1] sampled finely enough that linear interpolation stays within 1e-6 of it (the
// sRGB curve's error is about 1e-8): a photo has millions of samples and pow/cbrt cost ~20 ns.
class Curve {
public:
  explicit Curve(float (*f)(float)) {
    for (int i = 0; i <= kSteps; ++i) table_[std::size_t(i)] = f(float(i) / kSteps);
  }
  float operator()(float x) const {
    const float t = std::clamp(x, 0.0f, 1.0f) * kSteps;
    const int i = std::min(int(t), kSteps - 1);
    return table_[std::size_t(i)] + (t - float(i)) * (table_[std::size_t(i) + 1] - table_[std::size_t(i)]);
  }

private:
  static constexpr int kSteps = 8192;
  std::array<float, kSteps + 1> table_{};
};

cv::Mat convertEach(const cv::Mat& src, const Curve& convert) {
  CV_Assert(src.depth() == CV_32F);
  cv::Mat dst(src.size(), src.type());
  const int width = src.cols * src.channels();
  for (int y = 0; y < src.rows; ++y) {
    const float* in = src.ptr<float>(y);
    float* out = dst.ptr<float>(y);
    for (int x = 0; x < width; ++x) out[x] = convert(in[x]);
  }
  return dst;
}

float labCurve(float t) { return t > 0.008856f ? std::cbrt(t) : 7.787f * t + 16.0f / 116.0f; }

}  // namespace

cv::Mat srgbToLinear(const cv::Mat& srgb) {
  static const Curve curve(solidtex::srgbToLinear);
  return convertEach(srgb, curve);
}

cv::Mat linearToSrgb(const cv::Mat& linear) {
  static const Curve curve(solidtex::linearToSrgb);
  return convertEach(linear, curve);
}

cv::Mat linearToLab(const cv::Mat& linear) {
  CV_Assert(linear.type() == CV_32FC3);
  static const Curve f(labCurve);
  cv::Mat lab(linear.size(), CV_32FC3);
  for (int y = 0; y < linear.rows; ++y) {
    const auto* in = linear.ptr<cv::Vec3f>(y);
    auto* out = lab.ptr<cv::Vec3f>(y);
    for (int x = 0; x < linear.cols; ++x) {
      const float r = in[x][0], g = in[x][1], b = in[x][2];
      // sRGB primaries, D65 white (X and Z normalised by the white point).
      const float fx = f((0.412453f * r + 0.357580f * g + 0.180423f * b) / 0.950456f);
      const float fy = f(0.212671f * r + 0.715160f * g + 0.072169f * b);
      const float fz = f((0.019334f * r + 0.119193f * g + 0.950227f * b) / 1.088754f);
      out[x] = {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
    }
  }
  return lab;
}

}  // namespace solidtex::segmentation::detail
