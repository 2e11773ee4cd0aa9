#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "common/srgb.h"
#include "io/imageIO.h"
#include "segmentation/analyzeExemplar.h"
#include "testHelpers.h"

namespace solidtex {
namespace {

struct Block {
  cv::Rect rect;
  cv::Vec3f srgb;
};

// Rectangles drawn in a mask (exact areas) and in a photo (known colours).
ExemplarStats analyzeBlocks(const std::vector<Block>& blocks, cv::Size size, const cv::Vec3f& background) {
  cv::Mat mask = cv::Mat::zeros(size, CV_8UC1);
  cv::Mat photo(size, CV_32FC3, cv::Scalar(background[0], background[1], background[2]));
  for (const Block& b : blocks) {
    mask(b.rect).setTo(255);
    photo(b.rect).setTo(cv::Scalar(b.srgb[0], b.srgb[1], b.srgb[2]));
  }
  const std::string path = (test::freshTempDir() / "blocks.png").string();
  writeImage(path, mask);
  SegmentationOptions options;
  options.maskPath = path;
  options.split = false;
  options.minArea = 0;
  return analyzeExemplar(photo, "blocks", options);
}

const cv::Vec3f kGrey(0.5f, 0.5f, 0.5f), kRed(0.8f, 0.1f, 0.1f);

TEST(SegmentationStatistics, HistogramAndSizePairsOfAHandMadeCase) {
  const std::vector<Block> blocks{{{10, 10, 10, 10}, kRed}, {{40, 10, 10, 10}, kRed},
                                  {{70, 10, 10, 20}, kRed}, {{10, 50, 20, 10}, kRed},
                                  {{50, 50, 30, 30}, kRed}, {{0, 100, 40, 40}, kRed}};
  const ExemplarStats stats = analyzeBlocks(blocks, {120, 150}, kGrey);
  ASSERT_EQ(stats.particles.size(), 6u);

  // Areas 100, 100, 200, 200, 900; the 40x40 block touches the border and is left out.
  const AreaHistogram& h = stats.histogram;
  EXPECT_DOUBLE_EQ(h.edges[0], 100);
  EXPECT_DOUBLE_EQ(h.edges[1], 180);
  EXPECT_DOUBLE_EQ(h.edges[10], 900);
  const std::array<int, 10> counts{2, 2, 0, 0, 0, 0, 0, 0, 0, 1};
  EXPECT_EQ(h.counts, counts);
  EXPECT_DOUBLE_EQ(h.ratios[0], 0.4);
  EXPECT_DOUBLE_EQ(h.ratios[1], 0.4);
  EXPECT_DOUBLE_EQ(h.ratios[9], 0.2);

  ASSERT_EQ(stats.sizePairs.size(), 4u);
  EXPECT_EQ(stats.sizePairs[0].width, 10);
  EXPECT_EQ(stats.sizePairs[0].height, 10);
  EXPECT_EQ(stats.sizePairs[0].count, 2);
  EXPECT_EQ(stats.sizePairs[1].width, 10);
  EXPECT_EQ(stats.sizePairs[1].height, 20);
  EXPECT_EQ(stats.sizePairs[2].width, 20);
  EXPECT_EQ(stats.sizePairs[2].height, 10);
  EXPECT_EQ(stats.sizePairs[3].width, 30);
  EXPECT_EQ(stats.sizePairs[3].count, 1);

  EXPECT_DOUBLE_EQ(stats.areaFraction, (100 + 100 + 200 + 200 + 900 + 1600) / double(120 * 150));
}

TEST(SegmentationStatistics, IdsFollowTheBoxesRowByRow) {
  // The right block is higher, so it comes first even though it lies further right.
  const ExemplarStats stats =
      analyzeBlocks({{{70, 10, 10, 10}, kRed}, {{10, 12, 10, 10}, kRed}}, {100, 60}, kGrey);
  ASSERT_EQ(stats.particles.size(), 2u);
  EXPECT_EQ(stats.particles[0].id, 1);
  EXPECT_EQ(stats.particles[0].box, cv::Rect(70, 10, 10, 10));
  EXPECT_EQ(stats.particles[1].id, 2);
  EXPECT_EQ(stats.particles[1].box, cv::Rect(10, 12, 10, 10));
}

TEST(SegmentationStatistics, ColorsMasksAndResiduals) {
  const ExemplarStats stats = analyzeBlocks({{{20, 20, 16, 12}, kRed}}, {80, 60}, kGrey);
  ASSERT_EQ(stats.particles.size(), 1u);
  const Particle2D& p = stats.particles[0];
  EXPECT_EQ(p.area, 16 * 12);
  EXPECT_EQ(p.mask.size(), p.box.size());
  EXPECT_EQ(cv::countNonZero(p.mask), 16 * 12);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(p.color[c], srgbToLinear(kRed[c]), 1e-6);
    EXPECT_NEAR(stats.backgroundColor[c], srgbToLinear(kGrey[c]), 1e-6);
  }
  ASSERT_EQ(p.residual.type(), CV_32FC3);
  EXPECT_LT(cv::norm(p.residual, cv::NORM_INF), 1e-6);
  EXPECT_EQ(cv::countNonZero(stats.backgroundMask), 80 * 60 - 16 * 12);
  EXPECT_EQ(stats.backgroundResidual.size(), cv::Size(80, 60));
  EXPECT_LT(cv::norm(stats.backgroundResidual, cv::NORM_INF), 1e-6);
}

TEST(SegmentationStatistics, ResidualIsColorMinusMeanInsideTheMask) {
  cv::Mat photo(60, 80, CV_32FC3, cv::Scalar(0.9, 0.9, 0.9));
  for (int y = 20; y < 40; ++y)
    for (int x = 20; x < 50; ++x) photo.at<cv::Vec3f>(y, x) = {0.1f + 0.01f * float(x - 20), 0.2f, 0.3f};
  const ExemplarStats stats = analyzeExemplar(photo, "ramp", {});
  ASSERT_EQ(stats.particles.size(), 1u);
  const Particle2D& p = stats.particles[0];
  ASSERT_EQ(p.box, cv::Rect(20, 20, 30, 20));
  EXPECT_GE(cv::countNonZero(p.mask), 30 * 20 - 4 * 4);  // corners may be rounded off
  for (int y = 0; y < p.box.height; ++y)
    for (int x = 0; x < p.box.width; ++x) {
      const cv::Vec3f pixel = photo.at<cv::Vec3f>(p.box.y + y, p.box.x + x);
      const cv::Vec3f r = p.residual.at<cv::Vec3f>(y, x);
      const bool inside = p.mask.at<uchar>(y, x) != 0;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(inside ? r[c] + p.color[c] : r[c], inside ? srgbToLinear(pixel[c]) : 0.0f, 1e-5);
    }
  EXPECT_LT(std::abs(cv::mean(p.residual)[0]), 1e-6);
}

TEST(SegmentationStatistics, OnlyBorderParticlesStillGiveAHistogram) {
  const ExemplarStats stats =
      analyzeBlocks({{{0, 0, 10, 10}, kRed}, {{70, 40, 10, 20}, kRed}}, {80, 60}, kGrey);
  ASSERT_EQ(stats.particles.size(), 2u);
  EXPECT_TRUE(stats.particles[0].border && stats.particles[1].border);
  int total = 0;
  for (int c : stats.histogram.counts) total += c;
  EXPECT_EQ(total, 2);
  EXPECT_EQ(stats.sizePairs.size(), 2u);
  // Every statistic (histogram, compare's photo areas and shapes) counts the same particles.
  EXPECT_EQ(statisticalParticles(stats.particles), (std::vector<std::size_t>{0, 1}));
}

TEST(SegmentationStatistics, StatisticalParticlesLeaveBorderOnesOutWhenOthersExist) {
  const ExemplarStats stats =
      analyzeBlocks({{{0, 0, 10, 10}, kRed}, {{30, 20, 10, 10}, kRed}}, {80, 60}, kGrey);
  ASSERT_EQ(stats.particles.size(), 2u);
  ASSERT_TRUE(stats.particles[0].border);
  EXPECT_EQ(statisticalParticles(stats.particles), (std::vector<std::size_t>{1}));
}

TEST(SegmentationStatistics, EqualAreasFillTheFirstBin) {
  const ExemplarStats stats =
      analyzeBlocks({{{10, 10, 10, 10}, kRed}, {{30, 10, 10, 10}, kRed}}, {60, 40}, kGrey);
  EXPECT_EQ(stats.histogram.counts[0], 2);
  for (int i = 1; i <= 10; ++i) EXPECT_GT(stats.histogram.edges[i], stats.histogram.edges[i - 1]);
}

// A ring is a particle with its hole filled; a disc lying in another ring's hole stays its own
// particle, and the gap around it, closed in by two particles, stays background.
TEST(SegmentationStatistics, HolesBelongToTheParticleAroundThem) {
  cv::Mat mask = cv::Mat::zeros(120, 220, CV_8UC1);
  cv::circle(mask, {60, 60}, 40, cv::Scalar(255), cv::FILLED);
  cv::circle(mask, {60, 60}, 25, cv::Scalar(0), cv::FILLED);
  cv::circle(mask, {160, 60}, 40, cv::Scalar(255), cv::FILLED);
  cv::circle(mask, {160, 60}, 25, cv::Scalar(0), cv::FILLED);
  cv::circle(mask, {160, 60}, 10, cv::Scalar(255), cv::FILLED);
  const std::string path = (test::freshTempDir() / "rings.png").string();
  writeImage(path, mask);
  SegmentationOptions options;
  options.maskPath = path;
  options.split = false;
  const ExemplarStats stats =
      analyzeExemplar(cv::Mat(mask.size(), CV_32FC3, cv::Scalar(0.5, 0.5, 0.5)), "rings", options);
  ASSERT_EQ(stats.particles.size(), 3u);
  cv::Mat disc = cv::Mat::zeros(mask.size(), CV_8UC1), inner = disc.clone(), outer = disc.clone(),
          ring = disc.clone();
  cv::circle(disc, {60, 60}, 40, cv::Scalar(255), cv::FILLED);
  cv::circle(outer, {160, 60}, 40, cv::Scalar(255), cv::FILLED);
  cv::circle(ring, {160, 60}, 25, cv::Scalar(255), cv::FILLED);
  cv::circle(inner, {160, 60}, 10, cv::Scalar(255), cv::FILLED);
  std::vector<double> areas;
  for (const Particle2D& p : stats.particles) areas.push_back(p.area);
  std::sort(areas.begin(), areas.end());
  EXPECT_EQ(areas[0], cv::countNonZero(inner));
  EXPECT_EQ(areas[1], cv::countNonZero(outer) - cv::countNonZero(ring));
  EXPECT_EQ(areas[2], cv::countNonZero(disc));
}

TEST(SegmentationStatistics, BinOfClampsToTheTenBins) {
  AreaHistogram h;
  for (int i = 0; i <= 10; ++i) h.edges[i] = 10.0 * i;
  EXPECT_EQ(h.binOf(-5), 0);
  EXPECT_EQ(h.binOf(0), 0);
  EXPECT_EQ(h.binOf(9.999), 0);
  EXPECT_EQ(h.binOf(10), 1);
  EXPECT_EQ(h.binOf(55), 5);
  EXPECT_EQ(h.binOf(100), 9);
  EXPECT_EQ(h.binOf(1000), 9);
}

}  // namespace
}  // namespace solidtex
