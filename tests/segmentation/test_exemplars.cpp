#include <string>

#include <gtest/gtest.h>

#include "io/imageIO.h"
#include "segmentation/analyzeExemplar.h"
#include "segmentation/detail/color.h"
#include "segmentation/detail/separateBackground.h"
#include "testHelpers.h"

namespace solidtex {
namespace {

ExemplarStats analyzeData(const std::string& name) {
  return analyzeExemplar(test::dataPath("particles/" + name), {});
}

int innerCount(const ExemplarStats& stats) {
  int n = 0;
  for (const Particle2D& p : stats.particles) n += !p.border;
  return n;
}

// Counted by eye: 14 candies, four of them cut by the frame (the green one on the right, the
// orange one at the bottom, and the green and brown ones in the bottom-left corner).
TEST(SegmentationExemplars, SmartiesEveryCandyOnce) {
  const ExemplarStats stats = analyzeData("smarties.png");
  EXPECT_EQ(stats.particles.size(), 14u);
  EXPECT_EQ(innerCount(stats), 10);
  EXPECT_GT(stats.areaFraction, 0.15);
  EXPECT_LT(stats.areaFraction, 0.30);
  // White paper: the background colour is bright and neutral.
  EXPECT_GT(stats.backgroundColor[0], 0.8f);
  EXPECT_GT(stats.backgroundColor[2], 0.8f);
}

TEST(SegmentationExemplars, Coins24) {
  const ExemplarStats stats = analyzeData("coins.png");
  EXPECT_EQ(stats.particles.size(), 24u);
  EXPECT_EQ(innerCount(stats), 24);
}

TEST(SegmentationExemplars, GravelHundredsOfGrains) {
  const ExemplarStats stats = analyzeData("gravel.png");
  EXPECT_GT(stats.particles.size(), 400u);
  EXPECT_LT(stats.particles.size(), 1500u);
  EXPECT_GT(stats.areaFraction, 0.45);  // the grains, not the shadowed gaps, are the particles
  EXPECT_EQ(stats.name, "gravel.png");
  EXPECT_EQ(stats.imageWidth, 512);
}

TEST(SegmentationExemplars, LeopardSpots) {
  const ExemplarStats stats = analyzeData("leopard.png");
  EXPECT_GE(stats.particles.size(), 18u);
  EXPECT_LE(stats.particles.size(), 40u);
  // Spots are dark on a tan ground.
  for (const Particle2D& p : stats.particles) EXPECT_LT(p.color[0], stats.backgroundColor[0]) << p.id;
}

TEST(SegmentationExemplars, InvertedCoinsGiveTheBackground) {
  const cv::Mat linear = segmentation::detail::srgbToLinear(loadPhoto(test::dataPath("particles/coins.png")));
  const cv::Mat coins = segmentation::detail::separateBackground(linear, 12, false);
  const cv::Mat background = segmentation::detail::separateBackground(linear, 12, true);
  EXPECT_LT(cv::countNonZero(coins & background), int(0.01 * double(coins.total())));  // small specks differ
  EXPECT_GT(cv::countNonZero(coins | background), int(0.99 * double(coins.total())));
}

}  // namespace
}  // namespace solidtex
