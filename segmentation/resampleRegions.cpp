#include "segmentation/resampleRegions.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <opencv2/core.hpp>

namespace solidtex {
namespace {

cv::Size resampledSize(const cv::Size& size, double factor) {
  return {std::max(1, int(std::lround(size.width * factor))),
          std::max(1, int(std::lround(size.height * factor)))};
}

// Along one axis, the weight of source sample `first + s` in output sample `outFirst + o` (row o,
// column s), on the one grid of the whole image, so that every region is sampled where the others
// are. Shrinking averages the source over each output sample's extent; enlarging interpolates.
cv::Mat axisWeights(int first, int count, int outFirst, int outCount, double factor) {
  cv::Mat weights = cv::Mat::zeros(outCount, count, CV_32F);
  for (int o = 0; o < outCount; ++o) {
    const int out = outFirst + o;
    if (factor < 1) {
      const double lo = out / factor, hi = (out + 1) / factor;
      for (int s = std::max(0, int(std::floor(lo)) - first); s < count && first + s < hi; ++s)
        weights.at<float>(o, s) =
            float((std::min(hi, first + s + 1.0) - std::max(lo, double(first + s))) * factor);
    } else {
      const double x = (out + 0.5) / factor - 0.5;
      const int s0 = int(std::floor(x));
      const double t = x - s0;
      if (s0 - first >= 0 && s0 - first < count) weights.at<float>(o, s0 - first) = float(1 - t);
      if (s0 + 1 - first >= 0 && s0 + 1 - first < count) weights.at<float>(o, s0 + 1 - first) = float(t);
    }
  }
  return weights;
}

// The inside of `mask` (source pixels from `origin`) on the output pixels of `target`.
cv::Mat resampleOnGrid(const cv::Mat& mask, cv::Point origin, const cv::Rect& target, double factor) {
  cv::Mat inside;
  cv::Mat(mask != 0).convertTo(inside, CV_32F, 1.0 / 255);
  const cv::Mat rows = axisWeights(origin.y, mask.rows, target.y, target.height, factor);
  const cv::Mat columns = axisWeights(origin.x, mask.cols, target.x, target.width, factor);
  const cv::Mat coverage = rows * inside * columns.t();
  return coverage >= 0.5f;
}

}  // namespace

cv::Mat resampleMask(const cv::Mat& mask, double factor) {
  return resampleOnGrid(mask, {0, 0}, cv::Rect({0, 0}, resampledSize(mask.size(), factor)), factor);
}

cv::Mat resampleLabels(const cv::Mat& labels, double factor) {
  CV_Assert(labels.type() == CV_32S);
  std::map<std::int32_t, cv::Rect> boxes;
  for (int y = 0; y < labels.rows; ++y)
    for (int x = 0; x < labels.cols; ++x)
      if (const std::int32_t id = labels.at<std::int32_t>(y, x); id > 0) boxes[id] |= cv::Rect(x, y, 1, 1);
  const cv::Size size = resampledSize(labels.size(), factor);
  cv::Mat out = cv::Mat::zeros(size, CV_32S);
  const cv::Rect whole(0, 0, size.width, size.height);
  for (const auto& [id, box] : boxes) {
    // The output pixels the region's box reaches, and a pixel more on each side for its edge.
    const cv::Point lo(int(std::floor(box.x * factor)) - 1, int(std::floor(box.y * factor)) - 1);
    const cv::Point hi(int(std::ceil((box.x + box.width) * factor)) + 1,
                       int(std::ceil((box.y + box.height) * factor)) + 1);
    const cv::Rect target = cv::Rect(lo, hi) & whole;
    if (target.empty()) continue;
    const cv::Mat mask = resampleOnGrid(labels(box) == id, box.tl(), target, factor);
    out(target).setTo(cv::Scalar(id), mask);
  }
  return out;
}

}  // namespace solidtex
