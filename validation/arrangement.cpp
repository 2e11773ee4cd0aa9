#include "validation/arrangement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace solidtex {

std::vector<double> windowFractions(const cv::Mat& labels, int side) {
  CV_Assert(labels.type() == CV_32S && side > 0);
  std::vector<double> fractions;
  for (int y0 = 0; y0 + side <= labels.rows; y0 += side)
    for (int x0 = 0; x0 + side <= labels.cols; x0 += side) {
      int filled = 0;
      for (int y = y0; y < y0 + side; ++y) {
        const std::int32_t* row = labels.ptr<std::int32_t>(y);
        filled += int(std::count_if(row + x0, row + x0 + side, [](std::int32_t id) { return id > 0; }));
      }
      fractions.push_back(double(filled) / double(side * side));
    }
  return fractions;
}

int arrangementWindowSide(double diameter, const Dims& dims, const cv::Size& photo) {
  const int smallest = std::min({dims.x, dims.y, dims.z, photo.width, photo.height});
  return std::clamp(int(std::lround(3 * diameter)), 4, std::max(4, smallest / 2));
}

std::vector<double> nearestNeighbourDistances(const std::vector<cv::Point2d>& centres,
                                              const std::vector<bool>& counted, cv::Size image) {
  std::vector<double> distances;
  // A few hundred centres per image: the quadratic scan is cheaper than building an index.
  for (std::size_t i = 0; i < centres.size(); ++i) {
    if (!counted[i]) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < centres.size(); ++j)
      if (j != i) nearest = std::min(nearest, cv::norm(centres[i] - centres[j]));
    const cv::Point2d& c = centres[i];
    const double edge = std::min({c.x + 0.5, c.y + 0.5, image.width - 0.5 - c.x, image.height - 0.5 - c.y});
    if (nearest <= edge) distances.push_back(nearest);
  }
  return distances;
}

double standardDeviation(const std::vector<double>& values) {
  if (values.size() < 2) return 0;
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
  double sum = 0;
  for (double v : values) sum += (v - mean) * (v - mean);
  return std::sqrt(sum / double(values.size()));
}

}  // namespace solidtex
