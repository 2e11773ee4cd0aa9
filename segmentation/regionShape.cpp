#include "segmentation/regionShape.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <opencv2/imgproc.hpp>

namespace solidtex {
namespace {

// Boundary crossings of the lines of one direction through a mask with a one-pixel empty frame.
int crossings(const cv::Mat& mask, int dx, int dy) {
  int count = 0;
  for (int y = 0; y < mask.rows; ++y)
    for (int x = 0; x < mask.cols; ++x) {
      const int px = x - dx, py = y - dy;
      const bool before =
          px >= 0 && py >= 0 && px < mask.cols && py < mask.rows && mask.at<std::uint8_t>(py, px);
      count += before != (mask.at<std::uint8_t>(y, x) != 0);
    }
  return count;
}

// Cauchy-Crofton: the perimeter is half the integral over directions of the line crossings per unit
// of line offset. Four directions, pi/4 apart; axis lines lie 1 apart, diagonal ones 1/sqrt(2).
double croftonPerimeter(const cv::Mat& framedMask) {
  const double axis = crossings(framedMask, 1, 0) + crossings(framedMask, 0, 1);
  const double diagonal = crossings(framedMask, 1, 1) + crossings(framedMask, 1, -1);
  return std::numbers::pi / 8 * (axis + diagonal / std::numbers::sqrt2);
}

}  // namespace

RegionShape measureRegion(const std::vector<cv::Point>& pixels) {
  RegionShape shape;
  if (pixels.empty()) return shape;
  const cv::Rect box = cv::boundingRect(pixels);
  // A frame of one empty pixel so every boundary crossing lies inside the mask.
  const cv::Point offset(1 - box.x, 1 - box.y);
  cv::Mat mask = cv::Mat::zeros(box.height + 2, box.width + 2, CV_8U);
  cv::Point2d sum(0, 0);
  for (const cv::Point& p : pixels) {
    mask.at<std::uint8_t>(p + offset) = 1;
    sum += cv::Point2d(p);
  }
  shape.area = double(pixels.size());
  shape.centroid = sum / shape.area;
  double xx = 0, yy = 0, xy = 0;
  for (const cv::Point& p : pixels) {
    const cv::Point2d d = cv::Point2d(p) - shape.centroid;
    xx += d.x * d.x, yy += d.y * d.y, xy += d.x * d.y;
  }
  // A pixel is a unit square: its own 1/12 per axis keeps a one-pixel line from an aspect of 0.
  xx = xx / shape.area + 1.0 / 12, yy = yy / shape.area + 1.0 / 12, xy /= shape.area;
  const double half = 0.5 * (xx + yy), root = std::sqrt(0.25 * (xx - yy) * (xx - yy) + xy * xy);
  shape.aspect = std::sqrt((half - root) / (half + root));
  shape.orientation = std::fmod(0.5 * std::atan2(2 * xy, xx - yy) + std::numbers::pi, std::numbers::pi);
  shape.perimeter = croftonPerimeter(mask);
  shape.roundness = 4 * std::numbers::pi * shape.area / (shape.perimeter * shape.perimeter);

  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  const auto outer = std::max_element(contours.begin(), contours.end(),
                                      [](const auto& a, const auto& b) { return a.size() < b.size(); });
  std::vector<cv::Point> hull;
  cv::convexHull(*outer, hull);
  const double hullArea = cv::contourArea(hull);
  shape.solidity = hullArea > 0 ? std::min(1.0, cv::contourArea(*outer) / hullArea) : 1.0;
  return shape;
}

}  // namespace solidtex
