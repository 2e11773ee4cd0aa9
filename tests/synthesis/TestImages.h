#pragma once
#include <cmath>

#include <opencv2/core.hpp>

#include "common/Random.h"

namespace solidtex::test {

/// Two flat colours: background `a`, random discs of `b` (radius 3..6) until about `fraction` of the
/// pixels are discs. CV_32FC3, RGB.
inline cv::Mat randomDiscs(int size, double fraction, std::uint64_t seed, cv::Vec3f a = {0.9f, 0.8f, 0.3f},
                           cv::Vec3f b = {0.1f, 0.2f, 0.6f}) {
  cv::Mat img(size, size, CV_32FC3, cv::Scalar(a[0], a[1], a[2]));
  Rng rng(seed);
  int covered = 0;
  while (covered < fraction * size * size) {
    const double cx = uniform01(rng) * size, cy = uniform01(rng) * size, r = 3 + 3 * uniform01(rng);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r && img.at<cv::Vec3f>(y, x) != b) {
          img.at<cv::Vec3f>(y, x) = b;
          ++covered;
        }
  }
  return img;
}

/// Uniform random colours. CV_32FC3.
inline cv::Mat randomImage(int w, int h, std::uint64_t seed) {
  cv::Mat img(h, w, CV_32FC3);
  Rng rng(seed);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      img.at<cv::Vec3f>(y, x) =
          cv::Vec3f(float(uniform01(rng)), float(uniform01(rng)), float(uniform01(rng)));
  return img;
}

/// A smooth, structured test image (sums of sines). CV_32FC3.
inline cv::Mat smoothImage(int w, int h) {
  cv::Mat img(h, w, CV_32FC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      img.at<cv::Vec3f>(y, x) = cv::Vec3f(0.5f + 0.4f * float(std::sin(x * 0.4) * std::cos(y * 0.3)),
                                          0.5f + 0.3f * float(std::sin((x + y) * 0.25)),
                                          0.5f + 0.2f * float(std::cos(x * 0.15 - y * 0.35)));
  return img;
}

}  // namespace solidtex::test
