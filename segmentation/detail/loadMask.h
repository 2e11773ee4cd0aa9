#pragma once
#include <string>

#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// Loads a user mask (white = particle) as CV_8U, 255 on particle pixels. It must have the
// photo's size; throws InputError otherwise or when it cannot be read.
cv::Mat loadMask(const std::string& path, const cv::Size& photoSize);

}  // namespace solidtex::segmentation::detail
