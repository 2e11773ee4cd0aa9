#pragma once
/// @file
/// A photo particle's residual split by scale: the shading across it and the grain within it.

#include <opencv2/core.hpp>

#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// The two scales of a particle's residual. Both CV_32FC3, box-sized, linear RGB, 0 outside the mask.
struct ResidualScales {
  cv::Mat shading;  ///< the residual smoothed within the particle: its light, shadow and broad veins
  cv::Mat grain;    ///< the rest: speckle and fine veins
};

/// Pixels: the shading is smoothed over about this many; finer detail is grain.
constexpr double kShadingSigma = 2.0;

/// `particle.residual` split by a Gaussian of `sigma` pixels within the particle's mask, divided by
/// the mask's own smoothing so that the outline does not pull the shading towards zero.
ResidualScales splitResidual(const Particle2D& particle, double sigma = kShadingSigma);

/// How grainy the particle looks: the root mean square of its grain (splitResidual) in CIE L*
/// units, over the pixels at least two pixels inside its outline (the outline's pixels mix with
/// the matrix), or one pixel in a particle too small for that. Shading, smooth across the
/// particle, does not count. NaN when fewer than nine pixels lie a pixel inside.
double grainContrast(const Particle2D& particle);

}  // namespace solidtex
