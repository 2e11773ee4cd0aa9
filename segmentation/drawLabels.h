#pragma once
#include <opencv2/core.hpp>

#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// A picture for checking the segmentation at a glance: the photo (CV_32FC3 sRGB) enlarged by a
/// whole factor so its short side is at least 512 pixels and a typical particle at least 32
/// pixels wide (long side at most 4096), each particle outlined with its id at its centre; inner
/// particles in yellow, border particles (left out of the histogram) in magenta. Returns CV_8UC3
/// RGB, ready for writeImage.
cv::Mat drawLabels(const cv::Mat& photoSrgb, const ExemplarStats& stats);

}  // namespace solidtex
