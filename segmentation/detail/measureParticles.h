#pragma once
#include <vector>

#include <opencv2/core.hpp>

#include "segmentation/ExemplarStats.h"

namespace solidtex::segmentation::detail {

// Measures every labelled particle (CV_32S labels, 0 = background, holes already filled) of a
// CV_32FC3 linear-RGB photo: outer contour, box, area, mean colour, mask and residual. Particles smaller than
// minArea are dropped. Returned in a deterministic order (box top, then left, then size) with ids 1..P.
std::vector<Particle2D> measureParticles(const cv::Mat& labels, const cv::Mat& linear, double minArea);

// Fills backgroundMask, backgroundColor, backgroundResidual and areaFraction of `stats` from its
// particles. With no background pixel at all, the background colour is the photo's mean.
void measureBackground(ExemplarStats& stats, const cv::Mat& linear);

}  // namespace solidtex::segmentation::detail
