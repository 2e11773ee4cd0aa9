#pragma once
/// @file
/// Regions seen at another resolution, as a camera at that resolution would see them.

#include <opencv2/core.hpp>

namespace solidtex {

/// A binary mask (CV_8U, non-zero inside) resampled by `factor` (sides rounded, at least 1): each
/// output pixel is inside when at least half of it is covered (area averaging), so edges come out
/// clean instead of with the jagged steps of nearest-neighbour sampling.
cv::Mat resampleMask(const cv::Mat& mask, double factor);

/// A label image (CV_32S, 0 background, regions of equal positive labels) resampled by `factor`,
/// each region as resampleMask would on the whole image's grid; where two would claim a pixel, the
/// later label keeps it.
cv::Mat resampleLabels(const cv::Mat& labels, double factor);

}  // namespace solidtex
