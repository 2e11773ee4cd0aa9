#include "validation/brickSeams.h"

#include <algorithm>
#include <stdexcept>

#include <opencv2/core.hpp>

#include "validation/arrangement.h"

namespace solidtex {
namespace {

// Plane `at` across axis 0 (x), 1 (y) or 2 (z), as a label image.
cv::Mat planeOf(const std::vector<std::int32_t>& ids, const Dims& dims, int axis, int at) {
  const int cols = axis == 0 ? dims.y : dims.x, rows = axis == 2 ? dims.y : dims.z;
  cv::Mat plane(rows, cols, CV_32S);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const std::size_t i = axis == 0   ? dims.index(at, c, r)
                            : axis == 1 ? dims.index(c, at, r)
                                        : dims.index(c, r, at);
      plane.at<std::int32_t>(r, c) = ids[i];
    }
  return plane;
}

bool nearInnerFace(int at, int edge, int extent, int depth) {
  for (int face = edge; face < extent; face += edge)
    if (at >= face - depth && at < face + depth) return true;
  return false;
}

}  // namespace

BrickSeams brickSeams(const std::vector<std::int32_t>& ids, const Dims& dims, int brickEdge, int depth,
                      int windowSide) {
  if (ids.size() != dims.count() || brickEdge <= 0 || depth <= 0 || windowSide <= 0)
    throw std::invalid_argument("brickSeams: ids, brick edge, depth and window side disagree");
  BrickSeams seams;
  std::vector<double> faceWindows, otherWindows;
  double faceFilled = 0, faceArea = 0, otherFilled = 0, otherArea = 0;
  const int extents[3] = {dims.x, dims.y, dims.z};
  for (int axis = 0; axis < 3; ++axis)
    for (int at = 0; at < extents[axis]; ++at) {
      const cv::Mat plane = planeOf(ids, dims, axis, at);
      const bool face = nearInnerFace(at, brickEdge, extents[axis], depth);
      const double filled = double(cv::countNonZero(plane > 0));
      (face ? faceFilled : otherFilled) += filled;
      (face ? faceArea : otherArea) += double(plane.total());
      (face ? seams.facePlanes : seams.otherPlanes) += 1;
      const std::vector<double> windows = windowFractions(plane, windowSide);
      auto& into = face ? faceWindows : otherWindows;
      into.insert(into.end(), windows.begin(), windows.end());
    }
  seams.faceFraction = faceArea > 0 ? faceFilled / faceArea : 0;
  seams.otherFraction = otherArea > 0 ? otherFilled / otherArea : 0;
  seams.faceWindowSpread = standardDeviation(faceWindows);
  seams.otherWindowSpread = standardDeviation(otherWindows);
  return seams;
}

}  // namespace solidtex
