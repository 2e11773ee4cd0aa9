#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// Clears the 8-connected components of a CV_8U mask that are smaller than minArea pixels.
void removeSmallComponents(cv::Mat& mask, double minArea);

// Sets the 4-connected holes (zero components) of a CV_8U mask smaller than minArea pixels.
void fillSmallHoles(cv::Mat& mask, double minArea);

// The median of each pixel and its four edge neighbours (CV_32F, edges replicated): it removes
// sensor noise but keeps the tip of a right-angled corner, which has three of the five inside.
cv::Mat crossMedian(const cv::Mat& image);

// Puts back the corner pixels a 3x3 median moved across the outlines of `mask` (CV_8U, non-zero
// inside): a right-angled tip has four of its nine inside, so that median rounds every corner of
// an angular particle by a pixel, and fills a notch the same way. Every pixel with two
// perpendicular edge neighbours inside and two outside (every step of a diagonal edge too) joins
// the pair whose mean `distance` (CV_32F, the colour distance from the background, larger inside)
// its own lies within a quarter of the step between the two means of; a pixel half-way up a soft
// edge stays as it is, and so does one where the distance does not rise inwards.
void restoreCorners(cv::Mat& mask, const cv::Mat& distance);

}  // namespace solidtex::segmentation::detail
