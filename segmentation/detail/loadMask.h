#pragma once
#include <string>

#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// Loads a user mask (white = particle) as CV_8U, 255 on particle pixels. It must have the
// photo's size; throws InputError otherwise or when it cannot be read.
cv::Mat loadMask(const std::string& path, const cv::Size& photoSize);

// Throws InputError, `name` first, unless the mask is the photo's size.
void checkMaskSize(const cv::Size& maskSize, const cv::Size& photoSize, const std::string& name);

}  // namespace solidtex::segmentation::detail
