#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

struct OtsuSplit {
  float threshold = 0;      // values > threshold form the upper class
  double separability = 0;  // between-class / total variance (Otsu's eta), 0 when undefined
  double lowerMean = 0, upperMean = 0;
  double lowerStddev = 0, upperStddev = 0;
};

// Otsu's threshold on a one-channel CV_32F image, over the pixels where `mask` is non-zero
// (all when empty). The histogram spans the 0.1 %..99.9 % quantiles so that a few outliers
// (specular highlights, dead pixels) cannot squeeze the useful range into a few bins.
OtsuSplit otsu(const cv::Mat& values, const cv::Mat& mask = {});

struct OtsuThreeClasses {
  float lower = 0, upper = 0;  // classes: <= lower, (lower, upper], > upper
  double separability = 0;     // between-class / total variance, 0 when undefined
};

// Otsu's criterion with two thresholds (three classes), on the same robust histogram as otsu().
OtsuThreeClasses otsuThreeClasses(const cv::Mat& values, const cv::Mat& mask = {});

}  // namespace solidtex::segmentation::detail
