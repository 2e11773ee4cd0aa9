#include "segmentation/detail/chooseBackground.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "segmentation/detail/shape.h"
#include "segmentation/detail/splitParticles.h"

namespace solidtex::detail {
namespace {

constexpr double kDecisionPixels = 512.0 * 512.0;

// Pixels of one body times its solidity.
double solidPixels(const cv::Mat& labels, int label, const cv::Rect& box, double minArea) {
  const cv::Mat body = labels(box) == label;
  const double area = cv::countNonZero(body);
  if (area < minArea) return 0;
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(body, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  std::vector<cv::Point> points;
  for (const auto& c : contours) points.insert(points.end(), c.begin(), c.end());
  return area * std::min(1.0, area / hullPixelArea(hullOf(points)));
}

}  // namespace

double compactness(const cv::Mat& classMask, double minArea) {
  const double total = cv::countNonZero(classMask);
  if (total == 0) return 0;
  const cv::Mat labels = labelParticles(classMask, true);
  const std::vector<cv::Rect> boxes = labelBoxes(labels);
  double solid = 0;
  for (int label = 1; label < int(boxes.size()); ++label)
    if (!boxes[std::size_t(label)].empty() && !touchesBorder(boxes[std::size_t(label)], labels.size()))
      solid += solidPixels(labels, label, boxes[std::size_t(label)], minArea);
  return solid / total;
}

bool upperIsBackground(const cv::Mat& upper, double minArea) {
  // A judgement on the whole photo: a copy of about a quarter megapixel shows the same bodies,
  // and cutting both classes of a large photo into bodies would cost seconds.
  const int factor = int(std::ceil(std::sqrt(double(upper.total()) / kDecisionPixels)));
  if (factor <= 1) return compactness(upper, minArea) < compactness(upper == 0, minArea);
  cv::Mat small;
  cv::resize(upper, small, cv::Size(upper.cols / factor, upper.rows / factor), 0, 0, cv::INTER_AREA);
  small = small >= 128;
  const double smallMinArea = minArea / double(factor * factor);
  return compactness(small, smallMinArea) < compactness(small == 0, smallMinArea);
}

}  // namespace solidtex::detail
