#include <gtest/gtest.h>

#include "TestImages.h"
#include "synthesis/detail/ExemplarPyramid.h"
#include "synthesis/detail/solidMeasures.h"
#include "synthesis/detail/upsample.h"

using namespace solidtex;
using namespace solidtex::synthesis;

TEST(Measures, ColorHistogramDistance) {
  const RgbImage ex = toRgbImage(test::randomDiscs(32, 0.3, 3));
  EXPECT_DOUBLE_EQ(colorHistogramDistance(ex.data.data(), std::size_t(ex.pixelCount()), ex), 0.0);
  // A volume of the background colour only: the distance is the discs' share.
  int disc = 0;
  for (int i = 0; i < ex.pixelCount(); ++i) disc += ex.data[3 * i] < 0.5f;
  const std::vector<float> flat(300, 0.0f);
  std::vector<float> background;
  for (int i = 0; i < 100; ++i) background.insert(background.end(), {0.9f, 0.8f, 0.3f});
  EXPECT_NEAR(colorHistogramDistance(background.data(), 100, ex), double(disc) / ex.pixelCount(), 1e-9);
}

TEST(Measures, PositionHistogramStats) {
  const auto even = positionHistogramStats({0, 1, 2, 3, 3, 2, 1, 0}, 4);
  EXPECT_DOUBLE_EQ(even.coverage, 1.0);
  EXPECT_NEAR(even.flatness, 1.0, 1e-12);
  EXPECT_NEAR(even.variation, 0.0, 1e-12);
  const auto one = positionHistogramStats({2, 2, 2, 2}, 4);
  EXPECT_DOUBLE_EQ(one.coverage, 0.25);
  EXPECT_NEAR(one.flatness, 0.0, 1e-12);
  const auto half = positionHistogramStats({0, 1, 0, 1}, 4);
  EXPECT_DOUBLE_EQ(half.coverage, 0.5);
  EXPECT_NEAR(half.flatness, 0.5, 1e-12);
}

TEST(Measures, SliceEnergyIsZeroForAConstantSolidAndLargerForNoise) {
  cv::Mat flat(16, 16, CV_32FC3, cv::Scalar(0.2, 0.4, 0.6));
  const RgbImage ex = toRgbImage(flat);
  WorkVolume v = randomVolume(12, ex, 1);
  SliceMeasureOptions o;
  o.neighborhood = 4;
  o.axisSamples = 90;
  o.obliqueSamples = 60;
  const SliceEnergy e = sliceEnergy(v, ex, o);
  EXPECT_NEAR(e.axis, 0.0, 1e-6);
  EXPECT_NEAR(e.oblique, 0.0, 1e-6);

  const RgbImage smooth = toRgbImage(test::smoothImage(24, 24));
  const WorkVolume noise = randomVolume(12, smooth, 2);
  const SliceEnergy en = sliceEnergy(noise, smooth, o);
  EXPECT_GT(en.axis, 0.01);
  EXPECT_GT(en.oblique, 0.0);
  // Deterministic.
  const SliceEnergy again = sliceEnergy(noise, smooth, o);
  EXPECT_EQ(en.axis, again.axis);
  EXPECT_EQ(en.oblique, again.oblique);
}
