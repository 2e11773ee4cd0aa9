#pragma once
#include <vector>

#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// Area of the convex hull of pixel positions, measured on the pixels' outline rather than through
// their centres, so that it compares with a pixel count (a filled disc gets solidity 1, not more).
double hullPixelArea(const std::vector<cv::Point>& hull);

// The convex hull of the given points.
std::vector<cv::Point> hullOf(const std::vector<cv::Point>& points);

// Bounding box of every label of a CV_32S label image, indexed by label (empty for unused ones).
std::vector<cv::Rect> labelBoxes(const cv::Mat& labels);

// Whether a box within an image of `size` reaches the image's edge.
bool touchesBorder(const cv::Rect& box, const cv::Size& size);

}  // namespace solidtex::segmentation::detail
