#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "segmentation/analyzeExemplar.h"
#include "segmentation/matrixExemplar.h"

namespace solidtex {
namespace {

// Red discs in a grey grain: the exemplar keeps the grain and nothing of the discs.
TEST(MatrixExemplar, FillsTheParticlesWithTheMatrixGrain) {
  const cv::Size size(160, 160);
  cv::RNG rng(3);
  cv::Mat grain(size, CV_32F), photo(size, CV_32FC3);
  rng.fill(grain, cv::RNG::NORMAL, 0.5, 0.08);
  cv::cvtColor(grain, photo, cv::COLOR_GRAY2RGB);
  for (int i = 0; i < 30; ++i)
    cv::circle(photo, {rng.uniform(0, size.width), rng.uniform(0, size.height)}, rng.uniform(6, 12),
               cv::Scalar(0.85, 0.1, 0.1), cv::FILLED);
  cv::min(cv::max(photo, 0.0), 1.0, photo);
  const ExemplarStats stats = analyzeExemplar(photo, "red on grey", {});

  const cv::Mat exemplar = matrixExemplar(stats);
  ASSERT_EQ(exemplar.size(), cv::Size(64, 64));
  cv::Mat channels[3];
  cv::split(exemplar, channels);
  double mostRed = 0;
  cv::minMaxLoc(channels[0] - channels[1], nullptr, &mostRed);
  EXPECT_LT(mostRed, 0.1);  // grey to within the 8-bit Lab round trip
  cv::Scalar mean, spread;
  cv::meanStdDev(channels[1], mean, spread);
  EXPECT_NEAR(mean[0], 0.5, 0.03);
  EXPECT_NEAR(spread[0] / 0.08, 1.0, 0.25);

  MatrixExemplarOptions tooMuch;
  tooMuch.minMatrixShare = 0.99;
  EXPECT_TRUE(matrixExemplar(stats, tooMuch).empty());
}

// A window of matrix alone has nothing to fill (OpenCV's shift-map fails on a mask with no hole).
TEST(MatrixExemplar, AWindowOfMatrixAloneIsKeptAsItIs) {
  cv::Mat photo(120, 200, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  cv::RNG rng(5);
  cv::Mat grain(photo.size(), CV_32FC3);
  rng.fill(grain, cv::RNG::NORMAL, 0, 0.05);
  photo += grain;
  for (int i = 0; i < 6; ++i)
    cv::circle(photo, {150 + (i % 2) * 25, 15 + i * 18}, 8, cv::Scalar(0.9, 0.2, 0.1), cv::FILLED);
  cv::min(cv::max(photo, 0.0), 1.0, photo);
  const ExemplarStats stats = analyzeExemplar(photo, "discs at the right", {});
  const cv::Mat exemplar = matrixExemplar(stats);
  ASSERT_EQ(exemplar.size(), cv::Size(64, 64));
  cv::Scalar mean = cv::mean(exemplar);
  EXPECT_NEAR(mean[0], mean[1], 0.02);
}

}  // namespace
}  // namespace solidtex
