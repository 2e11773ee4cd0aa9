#include "segmentation/detail/shape.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

namespace solidtex::segmentation::detail {

double hullPixelArea(const std::vector<cv::Point>& hull) {
  if (hull.empty()) return 0;
  // The polygon through pixel centres misses a half-pixel strip along its perimeter and about one
  // pixel at the corners.
  return cv::contourArea(hull) + cv::arcLength(hull, true) / 2 + 1;
}

std::vector<cv::Point> hullOf(const std::vector<cv::Point>& points) {
  std::vector<cv::Point> hull;
  if (!points.empty()) cv::convexHull(points, hull);
  return hull;
}

std::vector<cv::Rect> labelBoxes(const cv::Mat& labels) {
  CV_Assert(labels.type() == CV_32SC1);
  double maxLabel = 0;
  cv::minMaxLoc(labels, nullptr, &maxLabel);
  std::vector<cv::Rect> boxes(std::size_t(std::max(0.0, maxLabel)) + 1);
  for (int y = 0; y < labels.rows; ++y) {
    const int* l = labels.ptr<int>(y);
    for (int x = 0; x < labels.cols; ++x) {
      if (l[x] <= 0) continue;
      cv::Rect& b = boxes[std::size_t(l[x])];
      b = b.empty() ? cv::Rect(x, y, 1, 1) : (b | cv::Rect(x, y, 1, 1));
    }
  }
  return boxes;
}

bool touchesBorder(const cv::Rect& box, const cv::Size& size) {
  return box.x == 0 || box.y == 0 || box.br().x == size.width || box.br().y == size.height;
}

}  // namespace solidtex::segmentation::detail
