#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// A particle is what its outline encloses (paper 3.2: particles are contours): every background
// hole of `labels` (CV_32S, 0 = background) that only one particle surrounds (a coin's dark
// relief, a highlight on a candy, the pale centre of a rosette) becomes part of it. Gaps closed
// in by several particles (between packed grains) stay background.
void fillEnclosedHoles(cv::Mat& labels);

}  // namespace solidtex::segmentation::detail
