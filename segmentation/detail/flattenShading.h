#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// Removes smooth shading (uneven lighting, vignetting) from a CV_32FC3 Lab image: fits a
// quadratic surface in (x, y) to each channel over the background pixels (CV_8U mask) and
// subtracts its variation, keeping the background mean. A channel is left alone unless the
// surface explains a clear share of the background's variance, so textured but evenly lit
// backgrounds are untouched.
cv::Mat flattenShading(const cv::Mat& lab, const cv::Mat& backgroundMask);

}  // namespace solidtex::segmentation::detail
