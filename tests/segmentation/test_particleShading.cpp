#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <opencv2/imgproc.hpp>

#include "segmentation/particleShading.h"

namespace solidtex {
namespace {

// A disc particle of `radius` pixels and grey linear colour 0.2 (L* 51.8), its pixels given by
// `value(x, y)` as a multiple of that colour.
template <class Value>
Particle2D disc(int radius, Value value) {
  Particle2D p;
  const int side = 2 * radius + 3;
  p.box = cv::Rect(0, 0, side, side);
  p.mask = cv::Mat::zeros(side, side, CV_8U);
  cv::circle(p.mask, {side / 2, side / 2}, radius, 255, cv::FILLED);
  cv::Mat pixels(side, side, CV_32FC3, cv::Scalar(0, 0, 0));
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      if (p.mask.at<std::uint8_t>(y, x)) pixels.at<cv::Vec3f>(y, x) = cv::Vec3f::all(0.2f * value(x, y));
  const cv::Scalar mean = cv::mean(pixels, p.mask);
  p.color = cv::Vec3f(float(mean[0]), float(mean[1]), float(mean[2]));
  p.residual = cv::Mat::zeros(p.box.size(), CV_32FC3);
  cv::subtract(pixels, mean, p.residual, p.mask);
  return p;
}

// Light falling across a particle (a ramp of +-15 % over it) is shading, not grain.
TEST(GrainContrast, ShadingAcrossTheParticleIsNotGrain) {
  const Particle2D p = disc(14, [](int x, int) { return float(1 + 0.3 * (x / 30.0 - 0.5)); });
  EXPECT_LT(grainContrast(p), 0.3);
}

// A speckle scaling each pixel's linear colour by 1 + s n (n standard normal) changes L* by about
// s (L* + 16) / 3 (dL* / d ln Y at this grey), 2.26 L* units for s = 0.1; taking off its smoothing
// by a Gaussian of sigma 2 keeps 1 - 2 g(0) + sum g^2 = 1 - 3 / (16 pi) of a white speckle's variance.
TEST(GrainContrast, ReadsASpeckleInLightnessUnits) {
  std::mt19937 rng(3);
  std::normal_distribution<float> normal;
  const Particle2D p = disc(14, [&](int, int) { return 1 + 0.1f * normal(rng); });
  const double expected = 0.1 * (51.84 + 16) / 3 * std::sqrt(1 - 3 / (16 * M_PI));
  EXPECT_NEAR(grainContrast(p), expected, 0.1 * expected);
}

// Too small to have nine pixels a pixel inside its outline: no reading.
TEST(GrainContrast, ATinyParticleHasNoReading) {
  EXPECT_TRUE(std::isnan(grainContrast(disc(1, [](int, int) { return 1.0f; }))));
  EXPECT_FALSE(std::isnan(grainContrast(disc(3, [](int, int) { return 1.0f; }))));
}

}  // namespace
}  // namespace solidtex
