#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// Clears the 8-connected components of a CV_8U mask that are smaller than minArea pixels.
void removeSmallComponents(cv::Mat& mask, double minArea);

// Sets the 4-connected holes (zero components) of a CV_8U mask smaller than minArea pixels.
void fillSmallHoles(cv::Mat& mask, double minArea);

}  // namespace solidtex::segmentation::detail
