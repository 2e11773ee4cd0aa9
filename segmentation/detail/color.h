#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// Whole-image versions of srgbToLinear / linearToSrgb for float images of any channel count.
cv::Mat srgbToLinear(const cv::Mat& srgb);
cv::Mat linearToSrgb(const cv::Mat& linear);

// CIE L*a*b* (D65; L in [0,100]) of a CV_32FC3 linear-RGB image, as OpenCV's RGB2Lab computes it
// but from linear values (no second gamma decode) and several times faster than its float path.
cv::Mat linearToLab(const cv::Mat& linear);

}  // namespace solidtex::segmentation::detail
