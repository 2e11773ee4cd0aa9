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
  double roundness = 1;    ///< 4 pi area / perimeter^2: 1 for a disc, lower for elongated or ragged regions
  double aspect = 1;       ///< minor / major axis of the pixels' second moments: 1 for a disc
  double orientation = 0;  ///< radians in [0, pi): the major axis from the image's x towards its y (down)
  cv::Point2d centroid;    ///< mean pixel position
};

/// Measures a region given as its pixels (any order, no repeats).
RegionShape measureRegion(const std::vector<cv::Point>& pixels);

/// Regions at most this round have an orientation worth comparing; a rounder one's major axis
/// turns with single pixels.
inline constexpr double kOrientedAspect = 0.8;

/// Solidity, roundness, aspect and orientation of many regions, one column each, for distribution
/// distances; orientations of the regions elongated enough to have one (kOrientedAspect).
struct ShapeColumns {
  std::vector<double> solidity, roundness, aspect, orientation;
  void add(const RegionShape& shape) {
    solidity.push_back(shape.solidity);
    roundness.push_back(shape.roundness);
    aspect.push_back(shape.aspect);
    if (shape.aspect <= kOrientedAspect) orientation.push_back(shape.orientation);
  }
};

}  // namespace solidtex
