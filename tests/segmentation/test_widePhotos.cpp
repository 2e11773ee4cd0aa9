// Photos wider than 4096 pixels: OpenCV 4.6's precise distance transform squares coordinates in
// float and goes wrong past column 4096, which made bogus particles there.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "io/imageIO.h"
#include "segmentation/analyzeExemplar.h"
#include "segmentation/detail/distanceTransform.h"
#include "segmentation/detail/splitParticles.h"
#include "testHelpers.h"

namespace solidtex {
namespace {

using test::Disc;

const cv::Vec3f kPaper(0.85f, 0.82f, 0.78f);

cv::Mat bruteForceDistance(const cv::Mat& mask) {
  std::vector<cv::Point> zeros;
  cv::findNonZero(mask == 0, zeros);
  cv::Mat distance(mask.size(), CV_32F);
  for (int y = 0; y < mask.rows; ++y)
    for (int x = 0; x < mask.cols; ++x) {
      double best = std::hypot(mask.cols, mask.rows);
      for (const cv::Point& z : zeros) best = std::min(best, std::hypot(x - z.x, y - z.y));
      distance.at<float>(y, x) = float(best);
    }
  return distance;
}

TEST(SegmentationWidePhotos, DistanceTransformIsExact) {
  cv::RNG rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    cv::Mat mask(rng.uniform(1, 40), rng.uniform(1, 40), CV_8UC1);
    rng.fill(mask, cv::RNG::UNIFORM, 0, 256);
    mask = mask > rng.uniform(200, 256);  // sparse zeros, sometimes none
    EXPECT_LE(cv::norm(segmentation::detail::euclideanDistance(mask), bruteForceDistance(mask), cv::NORM_INF),
              1e-4)
        << "trial " << trial << ", " << mask.cols << "x" << mask.rows;
  }
}

TEST(SegmentationWidePhotos, DistanceTransformIsExactOnLongRows) {
  cv::Mat mask(9, 9000, CV_8UC1, cv::Scalar(255));
  mask.col(100).setTo(0);
  mask.at<uchar>(4, 8500) = 0;
  const cv::Mat distance = segmentation::detail::euclideanDistance(mask);
  for (int x : {0, 100, 4095, 4096, 4097, 4098, 6000, 8300, 8499, 8999}) {
    const double expected = std::min(std::abs(x - 100.0), std::hypot(x - 8500.0, 0 - 4.0));
    EXPECT_NEAR(distance.at<float>(0, x), expected, 1e-3) << x;
    EXPECT_NEAR(distance.at<float>(4, x), std::min(std::abs(x - 100.0), std::abs(x - 8500.0)), 1e-3) << x;
  }
  EXPECT_EQ(cv::countNonZero(segmentation::detail::euclideanDistance(cv::Mat::zeros(8, 8192, CV_8UC1))), 0);
}

TEST(SegmentationWidePhotos, EmptyWideMaskHasNoParticles) {
  double most = 0;
  cv::minMaxLoc(segmentation::detail::labelParticles(cv::Mat::zeros(8, 8192, CV_8UC1), true), nullptr, &most);
  EXPECT_EQ(most, 0);
}

TEST(SegmentationWidePhotos, UniformWidePhotoHasNoParticles) {
  const cv::Mat white(8, 8192, CV_32FC3, cv::Scalar(1, 1, 1));
  EXPECT_THROW(analyzeExemplar(white, "white", {}), InputError);
}

TEST(SegmentationWidePhotos, DiscsPastColumn4096AreFoundWhole) {
  const std::vector<Disc> discs{{{300, 60}, 30, {0.3f, 0.2f, 0.1f}},
                                {{4150, 60}, 40, {0.7f, 0.1f, 0.1f}},
                                {{4400, 55}, 25, {0.1f, 0.5f, 0.2f}},
                                {{4700, 65}, 35, {0.2f, 0.2f, 0.7f}},
                                {{5050, 60}, 30, {0.3f, 0.2f, 0.1f}}};
  const ExemplarStats stats = analyzeExemplar(test::discPhoto({5120, 120}, kPaper, discs, 0.02), "wide", {});
  ASSERT_EQ(stats.particles.size(), discs.size());
  for (const Disc& d : discs) {
    const auto found = std::find_if(stats.particles.begin(), stats.particles.end(), [&](const Particle2D& p) {
      const cv::Point2f centre = (cv::Point2f(p.box.tl()) + cv::Point2f(p.box.br())) * 0.5f;
      return cv::norm(centre - d.centre) < 2;
    });
    ASSERT_NE(found, stats.particles.end()) << "disc at x " << d.centre.x;
    EXPECT_NEAR(found->area, CV_PI * d.radius * d.radius, 0.03 * CV_PI * d.radius * d.radius) << d.centre.x;
  }
}

TEST(SegmentationWidePhotos, CoinsTiledAcrossKeepTheirCountAndFraction) {
  const cv::Mat coins = loadPhoto(test::dataPath("particles/coins.png"));
  const ExemplarStats one = analyzeExemplar(coins, "coins", {});
  cv::Mat row;
  cv::repeat(coins, 1, 12, row);
  ASSERT_GT(row.cols, 4096);
  // The noise filter scales with the photo: keep the single photo's, so the same specks count.
  SegmentationOptions sameFilter;
  sameFilter.minArea = one.minArea;
  const ExemplarStats tiled = analyzeExemplar(row, "coins x12", sameFilter);
  EXPECT_EQ(tiled.particles.size(), 12 * one.particles.size());
  EXPECT_NEAR(tiled.areaFraction, one.areaFraction, 0.005);
}

}  // namespace
}  // namespace solidtex
