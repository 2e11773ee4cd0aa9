#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// Automatic two-class separation of a photo (CV_32FC3, linear RGB) into particles and background.
// Returns a CV_8U mask, 255 on particle pixels, with components and holes smaller than minArea
// cleaned away; all zero when the photo shows no clear two-class contrast. `invert` swaps the
// classes.
cv::Mat separateBackground(const cv::Mat& linear, double minArea, bool invert);

}  // namespace solidtex::segmentation::detail
