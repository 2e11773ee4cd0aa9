#include <gtest/gtest.h>

#include "synthesis/detail/discreteSolve.h"
#include "synthesis/detail/histograms.h"

using namespace solidtex::synthesis::detail;

TEST(Histograms, ColorWeightFollowsEquation3) {
  // Excess only where the synthesised histogram is above the exemplar's: 0.5 (channel 0) + 0.25 (channel 2).
  EXPECT_DOUBLE_EQ(colorHistogramWeight(2.0, {1.5, 0.5, 1.25}, {1.0, 1.0, 1.0}), 2.0 / 1.75);
  EXPECT_DOUBLE_EQ(colorHistogramWeight(3.0, {0.2, 0.5, 1.0}, {1.0, 1.0, 1.0}), 3.0);
  EXPECT_DOUBLE_EQ(colorHistogramWeight(1.0, {4.0, 3.0, 2.0}, {1.0, 1.0, 1.0}), 1.0 / 7.0);
}

TEST(Histograms, PositionWeightFollowsEquation4) {
  EXPECT_DOUBLE_EQ(positionHistogramWeight(1.0, 5.0, 2.0), 0.25);  // H - theta = 3
  EXPECT_DOUBLE_EQ(positionHistogramWeight(0.8, 1.0, 2.0), 0.8);   // under-used: kept
  EXPECT_DOUBLE_EQ(positionHistogramWeight(0.8, 2.0, 2.0), 0.8);   // exactly even: kept
  EXPECT_DOUBLE_EQ(positionHistogramWeight(3.0, 2.5, 2.0), 2.0);   // 3 / 1.5
}

TEST(Histograms, IndexDistanceFollowsEquations5And6) {
  EXPECT_DOUBLE_EQ(indexHistogramWeight(10.0, 4.0), 7.0);
  EXPECT_DOUBLE_EQ(indexHistogramWeight(3.0, 4.0), 1.0);
  EXPECT_DOUBLE_EQ(indexHistogramDistance(0.5, 10.0, 4.0), 3.5);
  EXPECT_DOUBLE_EQ(indexHistogramDistance(0.5, 3.0, 4.0), 0.5);
}

TEST(Histograms, ExpectedCountsAreEvenOrFollowTheControl) {
  const auto even = expectedCounts(100.0, 4);
  for (double v : even) EXPECT_DOUBLE_EQ(v, 25.0);
  const auto controlled = expectedCounts(100.0, 4, {1.0f, 1.0f, 2.0f, 0.0f});
  EXPECT_DOUBLE_EQ(controlled[0], 25.0);
  EXPECT_DOUBLE_EQ(controlled[2], 50.0);
  EXPECT_DOUBLE_EQ(controlled[3], 0.0);
}

TEST(Histograms, ChannelHistogramDensities) {
  // Four colours, 4 bins: red channel values land in bins 0, 0, 1, 3.
  const float rgb[] = {0.0f, 0.5f, 0.9f, 0.1f, 0.5f, 0.9f, 0.3f, 0.5f, 0.9f, 1.0f, 0.5f, 0.9f};
  ChannelHistograms h = channelHistograms(rgb, 4, 4);
  EXPECT_EQ(h.counts[0][0], 2);
  EXPECT_EQ(h.counts[0][3], 1);
  EXPECT_DOUBLE_EQ(h.density(0, 0), 2.0);  // half of the values in a quarter of the range
  EXPECT_DOUBLE_EQ(h.density(1, 2), 4.0);
  h.add(rgb, -1);
  EXPECT_EQ(h.total, 3);
  EXPECT_EQ(h.counts[0][0], 1);
}

TEST(Histograms, PositionHistogramCounts) {
  const auto h = positionHistogramOf({0, 2, 2, -1, 3}, 4);
  EXPECT_EQ(h, (std::vector<std::int64_t>{1, 0, 2, 1}));
}
