#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// Exact Euclidean distance (CV_32F) from every pixel of a CV_8U mask to the nearest zero pixel:
// 0 on zero pixels; hypot(width, height), farther than any distance inside the image, everywhere
// when the mask has no zero pixel. What cv::distanceTransform(DIST_L2, DIST_MASK_PRECISE) promises,
// but exact at any size: OpenCV 4.6 squares coordinates in float, which goes wrong on rows longer
// than 4096 pixels (2^24 = 4096^2), so pixels past x = 4096 get distances to the wrong column.
cv::Mat euclideanDistance(const cv::Mat& mask);

}  // namespace solidtex::segmentation::detail
