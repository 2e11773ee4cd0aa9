#include "segmentation/resampleRegions.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <opencv2/imgproc.hpp>

namespace solidtex {

cv::Mat resampleMask(const cv::Mat& mask, double factor) {
  const cv::Size size(std::max(1, int(std::lround(mask.cols * factor))), std::max(1, int(std::lround(mask.rows * factor))));
  cv::Mat coverage;
  cv::Mat(mask != 0).convertTo(coverage, CV_32F, 1.0 / 255);
  cv::resize(coverage, coverage, size, 0, 0, factor < 1 ? cv::INTER_AREA : cv::INTER_LINEAR);
  return coverage >= 0.5f;
}

cv::Mat resampleLabels(const cv::Mat& labels, double factor) {
  CV_Assert(labels.type() == CV_32S);
  std::map<std::int32_t, cv::Rect> boxes;
  for (int y = 0; y < labels.rows; ++y)
    for (int x = 0; x < labels.cols; ++x)
      if (const std::int32_t id = labels.at<std::int32_t>(y, x); id > 0) boxes[id] |= cv::Rect(x, y, 1, 1);
  const cv::Size size(std::max(1, int(std::lround(labels.cols * factor))), std::max(1, int(std::lround(labels.rows * factor))));
  cv::Mat out = cv::Mat::zeros(size, CV_32S);
  const cv::Rect whole(0, 0, size.width, size.height);
  for (const auto& [id, box] : boxes) {
    // A pixel of margin, so the region's edge falls inside the averaged area.
    const cv::Rect framed = (box + cv::Size(2, 2) - cv::Point(1, 1)) & cv::Rect(0, 0, labels.cols, labels.rows);
    const cv::Mat mask = resampleMask(labels(framed) == id, factor);
    const cv::Rect target = cv::Rect(cv::Point(int(std::lround(framed.x * factor)), int(std::lround(framed.y * factor))),
                                     mask.size()) & whole;
    out(target).setTo(cv::Scalar(id), mask(cv::Rect(0, 0, target.width, target.height)));
  }
  return out;
}

} // namespace solidtex
