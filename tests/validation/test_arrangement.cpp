#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "common/Random.h"
#include "validation/arrangement.h"

namespace solidtex {
namespace {

double mean(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

TEST(Arrangement, ALatticeFillsEveryWindowAlike) {
  cv::Mat labels = cv::Mat::zeros(240, 240, CV_32S);
  std::vector<cv::Point2d> centres;
  int id = 1;
  for (int y = 4; y < 240; y += 12)
    for (int x = 4; x < 240; x += 12) {
      labels(cv::Rect(x - 3, y - 3, 6, 6)).setTo(id++);
      centres.push_back({x - 0.5, y - 0.5});
    }
  const std::vector<double> fractions = windowFractions(labels, 48);
  ASSERT_EQ(fractions.size(), 25u);
  EXPECT_NEAR(mean(fractions), 36.0 / 144.0, 1e-12);
  EXPECT_NEAR(standardDeviation(fractions), 0, 1e-12);
  const std::vector<double> nn =
      nearestNeighbourDistances(centres, std::vector<bool>(centres.size(), true), labels.size());
  ASSERT_FALSE(nn.empty());
  for (double d : nn) EXPECT_NEAR(d, 12, 1e-9);
}

// Pixels filled independently with probability p: a window of s^2 pixels has a binomial fraction,
// standard deviation sqrt(p (1 - p)) / s.
TEST(Arrangement, WindowSpreadOfAnIndependentScatter) {
  Rng rng(7);
  const double p = 0.2;
  cv::Mat labels(480, 480, CV_32S);
  for (int y = 0; y < labels.rows; ++y)
    for (int x = 0; x < labels.cols; ++x) labels.at<std::int32_t>(y, x) = uniform01(rng) < p ? 1 : 0;
  for (int side : {8, 16}) {
    const double spread = standardDeviation(windowFractions(labels, side));
    EXPECT_NEAR(spread / (std::sqrt(p * (1 - p)) / side), 1, 0.12) << side;
  }
}

// Uniform random points of density lambda: mean nearest-neighbour distance 1 / (2 sqrt(lambda)),
// which the border method keeps unbiased.
TEST(Arrangement, NearestNeighboursOfAPoissonScatter) {
  Rng rng(11);
  const cv::Size image(400, 400);
  std::vector<cv::Point2d> centres(3000);
  for (auto& c : centres) c = {uniform01(rng) * image.width - 0.5, uniform01(rng) * image.height - 0.5};
  const std::vector<double> nn =
      nearestNeighbourDistances(centres, std::vector<bool>(centres.size(), true), image);
  const double lambda = double(centres.size()) / image.area();
  EXPECT_GT(nn.size(), 2500u);
  EXPECT_NEAR(mean(nn) * 2 * std::sqrt(lambda), 1, 0.05);
}

TEST(Arrangement, UncountedCentresAreNeighboursOnly) {
  const std::vector<cv::Point2d> centres{{10, 10}, {13, 14}, {50, 50}};
  const std::vector<double> nn = nearestNeighbourDistances(centres, {true, false, false}, cv::Size(100, 100));
  ASSERT_EQ(nn.size(), 1u);
  EXPECT_DOUBLE_EQ(nn[0], 5);
}

}  // namespace
}  // namespace solidtex
