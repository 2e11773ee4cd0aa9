#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// The side x side window of `linear` (CV_32FC3 linear RGB) with the most `known` pixels (CV_8U,
// ties: the first in raster order on a grid of 4), its other pixels filled cell by cell, from the
// holes' edges inwards, with the pieces of known pixels within a window's width around it whose
// surroundings match the cell's filled pixels best (masked matchTemplate in CIE Lab), each shifted
// in level by the difference of the two surroundings' means: the fill keeps the known pixels'
// grain and joins them without an edge. A cell with no such piece is filled by Telea's method.
// CV_32FC3 sRGB in [0,1]. Empty when fewer than `minShare` of the window's pixels are known.
// Not OpenCV xphoto's shift-map inpainting: it reads past its own buffer (memcheck, OpenCV 4.6),
// so its fill varied between runs.
cv::Mat exemplarWindow(const cv::Mat& linear, const cv::Mat& known, int side, double minShare);

}  // namespace solidtex::segmentation::detail
