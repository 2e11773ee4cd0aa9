#include "segmentation/detail/edgeDecision.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "segmentation/detail/markerWatershed.h"

namespace solidtex::segmentation::detail {
namespace {

constexpr float kReach = 3.0f * 1.4826f;  // 3 robust standard deviations (1.4826 MAD)

// Median + kReach MAD of the distances at or below `threshold`: how far the background's own
// colours reach. Robust, because the lower class also holds the dim parts of particles that the
// threshold missed.
float backgroundReach(const cv::Mat& distance, float threshold) {
  std::vector<float> v;
  v.reserve(distance.total());
  for (int y = 0; y < distance.rows; ++y) {
    const float* d = distance.ptr<float>(y);
    for (int x = 0; x < distance.cols; ++x)
      if (d[x] <= threshold) v.push_back(d[x]);
  }
  if (v.empty()) return threshold;
  const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  const float median = *mid;
  for (float& x : v) x = std::abs(x - median);
  std::nth_element(v.begin(), mid, v.end());
  return std::min(threshold, median + kReach * *mid);
}

cv::Mat gradientMagnitude(const cv::Mat& image) {
  cv::Mat gx, gy, magnitude;
  cv::Sobel(image, gx, CV_32F, 1, 0);
  cv::Sobel(image, gy, CV_32F, 0, 1);
  cv::magnitude(gx, gy, magnitude);
  return magnitude;
}

}  // namespace

cv::Mat backgroundByEdges(const cv::Mat& distance, const OtsuSplit& split) {
  return backgroundByEdges(distance, distance > split.threshold, split.threshold);
}

cv::Mat backgroundByEdges(const cv::Mat& distance, const cv::Mat& particleSeeds, float threshold) {
  CV_Assert(distance.type() == CV_32FC1 && particleSeeds.type() == CV_8UC1);
  enum : uchar { kUndecided = 0, kBackground = 1, kParticle = 2 };
  cv::Mat markers(distance.size(), CV_8UC1, cv::Scalar(kUndecided));
  markers.setTo(kBackground, distance <= backgroundReach(distance, threshold));
  markers.setTo(kParticle, particleSeeds);
  return markerWatershed(markers, gradientMagnitude(distance)) == kBackground;
}

}  // namespace solidtex::segmentation::detail
