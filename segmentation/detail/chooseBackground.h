#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// How much a class of pixels (CV_8U mask) looks like particles: it is cut into bodies the same way
// particles are (distance transform + convexity), and the share of its pixels that lie in bodies
// clear of the image border, weighted by each body's solidity (pixels / convex hull), is returned.
// Bodies smaller than minArea count as nothing.
double compactness(const cv::Mat& classMask, double minArea);

// True when `upper` (CV_8U, 255 on one class; the other class is its complement) is the
// background. Particles are compact bodies inside the frame; the background is what lies between
// them and runs out of the frame, so it is the less compact class. This holds whether the
// background is the larger class (candies on paper) or the smaller one (the shadowed gaps between
// packed gravel grains, which break into ragged pieces).
bool upperIsBackground(const cv::Mat& upper, double minArea);

// Pixels of compact bodies in a particle mask, as a share of all pixels: compactness times the
// mask's share. Of two readings of a photo, the one whose particles cover more of it in compact
// bodies is the likelier.
double solidShare(const cv::Mat& particles, double minArea);

// The middle of three classes by lightness (Otsu's two thresholds on `lightness`, CV_32F, smoothed
// first so the grain of a textured matrix does not scatter into the outer classes), returned
// (CV_8U, 255 on it) when it is less compact than both outer ones and each outer one holds a fair
// share of the photo: the matrix between particles of two tones, lighter and darker than it
// (light and dark pebbles in grey mortar). Empty otherwise.
cv::Mat middleLightnessClass(const cv::Mat& lightness, double minArea);

}  // namespace solidtex::segmentation::detail
