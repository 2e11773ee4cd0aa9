#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// The colour distance (CIE76 Delta E, CV_32F) of every pixel of a CV_32FC3 Lab image from the
// background's mean colour, lighting evened out over the background (CV_8U mask, non-zero on
// background).
cv::Mat colourDistance(const cv::Mat& lab, const cv::Mat& backgroundMask);

// colourDistance with the sensor noise taken off by a 3x3 median.
cv::Mat distanceFromBackground(const cv::Mat& lab, const cv::Mat& backgroundMask);

// How blurred the particles' outlines look, in pixels: the standard deviation of the Gaussian blur
// whose edge profile has the same width between a quarter and three quarters of the way from the
// background's distance to the particle's, the median over the outline pixels of `particles`
// (CV_8U, non-zero on particles) of the profiles of `distance` along the outline's normal. A sharp
// outline measures about 0.4 (the half-pixel step of sampling between pixels); 0 when no outline
// shows a clear contrast.
double measureOutlineBlur(const cv::Mat& distance, const cv::Mat& particles);

}  // namespace solidtex::segmentation::detail
