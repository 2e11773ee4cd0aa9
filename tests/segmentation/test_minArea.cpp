#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "segmentation/analyzeExemplar.h"
#include "testHelpers.h"

namespace solidtex {
namespace {

using test::Disc;

// 2500 dark discs of radius 3-5 px (28-79 px) on a light 1000^2 photo: each is smaller than the
// photo-size default alone (1000^2 / 10 000 = 100 px) would keep.
std::vector<Disc> smallDiscs() {
  std::vector<Disc> discs;
  for (int j = 0; j < 50; ++j)
    for (int i = 0; i < 50; ++i)
      discs.push_back({{float(10 + 20 * i + (j % 3)), float(10 + 20 * j + (i % 3))},
                       3.0f + float((i * 7 + j * 3) % 5) * 0.5f,
                       {0.2f, 0.25f, 0.5f}});
  return discs;
}

TEST(SegmentationMinArea, ManySmallParticlesAreKeptByDefault) {
  const cv::Mat photo = test::discPhoto({1000, 1000}, {0.8f, 0.75f, 0.7f}, smallDiscs(), 0.02);
  const ExemplarStats stats = analyzeExemplar(photo, "small.png", {});
  EXPECT_NEAR(double(stats.particles.size()), 2500.0, 0.02 * 2500);
  EXPECT_LT(stats.minArea, 28);
  EXPECT_LT(stats.areaShareBelowMinArea, 0.01);
}

TEST(SegmentationMinArea, RegionsDroppedAsTooSmallAreCounted) {
  const cv::Mat photo = test::discPhoto({1000, 1000}, {0.8f, 0.75f, 0.7f}, smallDiscs(), 0.02);
  SegmentationOptions options;
  options.minArea = 50;
  // What the drawn discs give: how many are smaller, and their share of the discs' area.
  cv::Mat labels, regions, centroids;
  const int count = cv::connectedComponentsWithStats(test::discMask({1000, 1000}, smallDiscs()), labels,
                                                     regions, centroids, 8, CV_32S);
  int smaller = 0;
  double all = 0, dropped = 0;
  for (int r = 1; r < count; ++r) {
    const int area = regions.at<int>(r, cv::CC_STAT_AREA);
    all += area;
    if (area < options.minArea) ++smaller, dropped += area;
  }
  ASSERT_GT(smaller, 500);
  const ExemplarStats stats = analyzeExemplar(photo, "small.png", options);
  EXPECT_NEAR(stats.regionsBelowMinArea, smaller, 0.05 * smaller);
  EXPECT_NEAR(stats.areaShareBelowMinArea, dropped / all, 0.05);
}

TEST(SegmentationMinArea, LargeParticlesKeepThePhotoSizeDefault) {
  const std::vector<Disc> discs{{{60, 60}, 20, {0.1f, 0.1f, 0.1f}}, {{150, 100}, 25, {0.1f, 0.1f, 0.1f}}};
  const ExemplarStats stats =
      analyzeExemplar(test::discPhoto({220, 180}, {0.8f, 0.8f, 0.8f}, discs), "big", {});
  EXPECT_EQ(stats.minArea, 8);
  EXPECT_EQ(stats.particles.size(), 2u);
}

}  // namespace
}  // namespace solidtex
