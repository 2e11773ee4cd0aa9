#include "segmentation/detail/outlineBlur.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "segmentation/detail/flattenShading.h"

namespace solidtex::segmentation::detail {
namespace {

constexpr float kReach = 5.0f;        // pixels either side of the outline a profile spans
constexpr float kStep = 0.25f;        // pixels between a profile's samples
constexpr float kLevelsFrom = 3.5f;   // the inside and outside levels are the samples this far out
constexpr float kMinContrast = 5.0f;  // Delta E between the levels: below it, no edge to measure
// Width between the 25 % and 75 % points of a Gaussian-blurred step, over its sigma: 2 x 0.6745.
constexpr double kQuartileWidth = 1.349;
constexpr int kSamples = int(2 * kReach / kStep) + 1;

// The image is at least two pixels on a side (measureOutlineBlur checks), so every pixel has a
// right and a lower neighbour to interpolate with once clamped.
float bilinear(const cv::Mat& image, float x, float y) {
  x = std::clamp(x, 0.f, float(image.cols - 1));
  y = std::clamp(y, 0.f, float(image.rows - 1));
  const int x0 = std::min(int(x), image.cols - 2), y0 = std::min(int(y), image.rows - 2);
  const float fx = x - float(x0), fy = y - float(y0);
  const float* top = image.ptr<float>(y0) + x0;
  const float* bottom = image.ptr<float>(y0 + 1) + x0;
  return (top[0] * (1 - fx) + top[1] * fx) * (1 - fy) + (bottom[0] * (1 - fx) + bottom[1] * fx) * fy;
}

float median(std::vector<float> values) {
  const auto mid = values.begin() + std::ptrdiff_t(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

bool isOutline(const cv::Mat& particles, int x, int y) {
  if (!particles.at<uchar>(y, x)) return false;
  constexpr std::array<std::array<int, 2>, 4> kNeighbours{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
  for (const auto& [dx, dy] : kNeighbours) {
    const int u = x + dx, v = y + dy;
    if (u >= 0 && v >= 0 && u < particles.cols && v < particles.rows && !particles.at<uchar>(v, u))
      return true;
  }
  return false;
}

// The 25-75 % width of the profile of `distance` through (x, y) along the unit normal n (pointing
// into the particle), in pixels; negative when the profile shows no clear step.
float quartileWidth(const cv::Mat& distance, float x, float y, cv::Point2f n) {
  std::array<float, kSamples> profile{};
  std::vector<float> outside, inside;
  for (int s = 0; s < kSamples; ++s) {
    const float t = -kReach + kStep * float(s);
    profile[std::size_t(s)] = bilinear(distance, x + t * n.x, y + t * n.y);
    if (t <= -kLevelsFrom) outside.push_back(profile[std::size_t(s)]);
    if (t >= kLevelsFrom) inside.push_back(profile[std::size_t(s)]);
  }
  const float low = median(outside), high = median(inside);
  if (high - low < kMinContrast) return -1;
  // The quarter point is where the profile first rises past it from outside, the three-quarter
  // point where it last stays below it seen from inside (noise may cross either more than once);
  // both interpolated between samples.
  const auto fraction = [&](int s) { return (profile[std::size_t(s)] - low) / (high - low); };
  const auto crossing = [&](int a, int b, float level) {
    const float fa = fraction(a), fb = fraction(b);
    return kStep * (float(a) + (fb != fa ? (level - fa) / (fb - fa) : 0.5f) * float(b - a));
  };
  int up = 1;
  while (up < kSamples - 1 && fraction(up) < 0.25f) ++up;
  int down = kSamples - 2;
  while (down > 0 && fraction(down) > 0.75f) --down;
  return std::max(0.f, crossing(down, down + 1, 0.75f) - crossing(up - 1, up, 0.25f));
}

}  // namespace

cv::Mat colourDistance(const cv::Mat& lab, const cv::Mat& backgroundMask) {
  CV_Assert(lab.type() == CV_32FC3 && backgroundMask.type() == CV_8UC1);
  const cv::Mat flat = flattenShading(lab, backgroundMask);
  cv::Mat diff, distance;
  cv::subtract(flat, cv::mean(flat, backgroundMask), diff);
  cv::multiply(diff, diff, diff);
  cv::transform(diff, distance, cv::Matx13f(1, 1, 1));
  cv::sqrt(distance, distance);
  return distance;
}

cv::Mat distanceFromBackground(const cv::Mat& lab, const cv::Mat& backgroundMask) {
  cv::Mat distance;
  cv::medianBlur(colourDistance(lab, backgroundMask), distance, 3);
  return distance;
}

double measureOutlineBlur(const cv::Mat& distance, const cv::Mat& particles) {
  CV_Assert(distance.rows >= 2 && distance.cols >= 2);
  CV_Assert(distance.type() == CV_32FC1 && particles.type() == CV_8UC1 &&
            distance.size() == particles.size());
  // The outline's normal from a softened mask: smooth where the pixel outline is a staircase.
  cv::Mat soft, gx, gy;
  particles.convertTo(soft, CV_32F, 1.0 / 255);
  cv::GaussianBlur(soft, soft, {0, 0}, 1.5);
  cv::Sobel(soft, gx, CV_32F, 1, 0);
  cv::Sobel(soft, gy, CV_32F, 0, 1);
  std::vector<float> widths;
  for (int y = 0; y < particles.rows; ++y)
    for (int x = 0; x < particles.cols; ++x) {
      if (!isOutline(particles, x, y)) continue;
      const cv::Point2f g{gx.at<float>(y, x), gy.at<float>(y, x)};
      const float norm = std::hypot(g.x, g.y);
      if (norm < 1e-6f) continue;
      if (const float w = quartileWidth(distance, float(x), float(y), g / norm); w >= 0) widths.push_back(w);
    }
  return widths.empty() ? 0 : median(widths) / kQuartileWidth;
}

}  // namespace solidtex::segmentation::detail
