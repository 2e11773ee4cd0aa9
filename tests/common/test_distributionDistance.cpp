#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "common/Random.h"
#include "common/distributionDistance.h"

namespace solidtex {
namespace {

std::vector<double> uniformSample(std::size_t n, Rng& rng) {
  std::vector<double> v(n);
  for (double& x : v) x = uniform01(rng);
  return v;
}

TEST(DistributionDistance, KsIsTheLargestGapBetweenTheCdfs) {
  EXPECT_DOUBLE_EQ(ksStatistic({1, 2, 3, 4}, {1, 2, 3, 4}), 0);
  EXPECT_DOUBLE_EQ(ksStatistic({1, 2}, {3, 4}), 1);
  EXPECT_DOUBLE_EQ(ksStatistic({1, 2, 3, 4}, {3, 4, 5, 6}), 0.5);
  EXPECT_DOUBLE_EQ(ksStatistic({}, {1}), 1);
}

TEST(DistributionDistance, W1IsTheAreaBetweenTheCdfs) {
  EXPECT_DOUBLE_EQ(wasserstein1({0, 1}, {0, 1}), 0);
  EXPECT_DOUBLE_EQ(wasserstein1({0, 1}, {2, 3}), 2);  // a shift by 2
  EXPECT_DOUBLE_EQ(wasserstein1({0}, {0, 1}), 0.5);
  EXPECT_DOUBLE_EQ(mean({1, 2, 6}), 3);
  EXPECT_DOUBLE_EQ(mean({}), 0);
}

// Samples of one distribution exceed the 5 % critical value in about 5 % of draws, at sizes as small
// as a photo of ten candies against a solid's sections.
TEST(DistributionDistance, KsCriticalValueIsExceededOneTimeInTwenty) {
  Rng rng(11);
  for (const auto& [n, m] : {std::pair<std::size_t, std::size_t>{10, 170}, {300, 2000}}) {
    int exceeded = 0;
    const int trials = 1000;
    for (int t = 0; t < trials; ++t)
      exceeded += ksStatistic(uniformSample(n, rng), uniformSample(m, rng)) > ksCritical95(n, m);
    EXPECT_GT(exceeded, trials * 0.02) << n << " vs " << m;
    EXPECT_LT(exceeded, trials * 0.08) << n << " vs " << m;
  }
  EXPECT_NEAR(ksCritical95(10, 170), 0.44, 0.01);
  EXPECT_DOUBLE_EQ(ksCritical95(0, 5), 1);
}

}  // namespace
}  // namespace solidtex
