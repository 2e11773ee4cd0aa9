#pragma once
/// @file
/// How particles are spread over an image: local crowdedness and spacing.

#include <vector>

#include <opencv2/core.hpp>

#include "common/Grid.h"

namespace solidtex {

/// Particle area fraction of each square window of `side` pixels that tiles the label image (CV_32S,
/// particles > 0) from its corner and lies wholly inside it. Their spread says how clustered the
/// particles are: evenly scattered particles give every window about the same fraction.
std::vector<double> windowFractions(const cv::Mat& labels, int side);

/// The side of the arrangement windows for particles of `diameter` voxels: a few diameters, and at
/// least two windows across the volume and across the photo (`photo` at the volume's scale).
int arrangementWindowSide(double diameter, const Dims& dims, const cv::Size& photo);

/// For each counted centre, the distance to its nearest other centre, kept only when that is no
/// farther than the image's edge (the border method: a nearer neighbour cannot hide beyond the edge).
std::vector<double> nearestNeighbourDistances(const std::vector<cv::Point2d>& centres,
                                              const std::vector<bool>& counted, cv::Size image);

/// Population standard deviation; 0 for fewer than two values.
double standardDeviation(const std::vector<double>& values);

}  // namespace solidtex
