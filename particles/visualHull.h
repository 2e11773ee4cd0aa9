#pragma once
#include <vector>

#include <Eigen/Core>
#include <opencv2/core/types.hpp>

#include "particles/HullMesh.h"

namespace solidtex {

/// One view of a visual hull (paper 3.4): a polygon in the view's image plane, seen along
/// the view direction with a parallel projection.
///
/// `rotation` maps the view's frame to hull space: its columns are the image x axis, the image
/// y axis and the viewing direction. A hull-space point p projects to (R^T p).x, (R^T p).y, so the
/// silhouette carves the prism { p : (R^T p).xy inside polygon }. `rotation` must be a proper
/// rotation (orthonormal, determinant +1).
struct Silhouette {
  std::vector<Eigen::Vector2d>
      polygon;  ///< in [-0.5,0.5]^2, any orientation; made simple by makeSimplePolygon
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
};

/// A photo contour as a silhouette polygon: simplified with cv::approxPolyDP to at most about
/// `vertices` vertices, then the contour's own axis-aligned box (the extent of its points) is
/// stretched to the square [-0.5,0.5]^2 (the paper's L x L normalisation, done per contour), with
/// image y flipped so the polygon looks as in the photo in a right-handed (x right, y up) frame.
/// The result is simple and counter-clockwise; empty when the contour encloses no area.
std::vector<Eigen::Vector2d> normalizeContour(const std::vector<cv::Point>& contour, int vertices);

/// A simple, counter-clockwise version of a closed polygon in the unit square, with a clearance of
/// 2^-10 (about 0.1 %) so that rounding the prisms built on it cannot make them touch themselves:
/// repeated and nearly collinear vertices and the tips of spikes narrower than that are dropped, and
/// where two edges come closer than that (or cross) the polygon is cut in two there, keeping the loop
/// with more area. Empty when nothing with area is left.
std::vector<Eigen::Vector2d> makeSimplePolygon(std::vector<Eigen::Vector2d> polygon);

/// The visual hull of the views inside the local cube [-0.5,0.5]^3 (paper 3.4): the exact
/// intersection (CGAL corefinement, exact constructions) of the cube with one prism per view,
/// rounded to doubles. Closed and outward oriented; empty when the prisms do not meet.
/// Throws std::invalid_argument when a rotation is not a proper rotation.
HullMesh visualHull(const std::vector<Silhouette>& views);

}  // namespace solidtex
