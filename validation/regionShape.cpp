#include "validation/regionShape.h"

#include <algorithm>
#include <cmath>
#include <limits>
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
      const bool before = px >= 0 && py >= 0 && px < mask.cols && py < mask.rows && mask.at<std::uint8_t>(py, px);
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

// Pixels whose centres lie in a convex polygon with integer vertices, row by row: the digital convex
// hull, which a digital disc or ellipse fills exactly.
double pixelsInConvexPolygon(const std::vector<cv::Point>& hull) {
  const auto [low, high] = std::minmax_element(hull.begin(), hull.end(), [](cv::Point a, cv::Point b) { return a.y < b.y; });
  double count = 0;
  for (int y = low->y; y <= high->y; ++y) {
    double left = std::numeric_limits<double>::infinity(), right = -left;
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const cv::Point p = hull[i], q = hull[(i + 1) % hull.size()];
      if (y < std::min(p.y, q.y) || y > std::max(p.y, q.y)) continue;
      const double x = p.y == q.y ? p.x : p.x + double(y - p.y) * (q.x - p.x) / double(q.y - p.y);
      const double other = p.y == q.y ? q.x : x;
      left = std::min({left, x, other});
      right = std::max({right, x, other});
    }
    if (right >= left) count += std::floor(right + 1e-9) - std::ceil(left - 1e-9) + 1;
  }
  return count;
}

} // namespace

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
  shape.perimeter = croftonPerimeter(mask);
  shape.roundness = 4 * std::numbers::pi * shape.area / (shape.perimeter * shape.perimeter);

  std::vector<cv::Point> hull;
  cv::convexHull(pixels, hull);
  shape.solidity = std::min(1.0, shape.area / std::max(1.0, pixelsInConvexPolygon(hull)));
  return shape;
}

} // namespace solidtex
