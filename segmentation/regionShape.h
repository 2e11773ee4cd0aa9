#pragma once
/// @file
/// Shape measures of one digital 2D region: a photo particle or a cross-section of a solid.

#include <vector>

#include <opencv2/core/types.hpp>

namespace solidtex {

/// Size, shape and position of one 8-connected region of pixels.
struct RegionShape {
  double area = 0;       ///< pixels
  double perimeter = 0;  ///< Crofton estimate over four directions: unbiased on digital discs and ellipses
  double solidity = 1;  ///< area / convex hull area of the outer contour through the boundary pixels' centres
  double roundness = 1;  ///< 4 pi area / perimeter^2: 1 for a disc, lower for elongated or ragged regions
  cv::Point2d centroid;  ///< mean pixel position
};

/// Measures a region given as its pixels (any order, no repeats).
RegionShape measureRegion(const std::vector<cv::Point>& pixels);

/// Solidity and roundness of many regions, one column each, for distribution distances.
struct ShapeColumns {
  std::vector<double> solidity, roundness;
  void add(const RegionShape& shape) {
    solidity.push_back(shape.solidity);
    roundness.push_back(shape.roundness);
  }
};

}  // namespace solidtex
