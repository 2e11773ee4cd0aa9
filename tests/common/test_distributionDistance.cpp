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

// Angles on a circle: Kuiper's statistic does not change with where the circle is cut, where the
// KS does; it is at least the KS.
TEST(DistributionDistance, KuiperIsTheKsOfACircle) {
  Rng rng(3);
  std::vector<double> a, b;
  for (int i = 0; i < 200; ++i) {
    a.push_back(std::fmod(0.1 * standardNormal(rng) + 10, 1.0));  // clustered around the cut at 0
    b.push_back(uniform01(rng) * 0.3 + 0.35);                     // around 0.5
  }
  const auto turned = [](std::vector<double> v, double by) {
    for (double& x : v) x = std::fmod(x + by, 1.0);
    return v;
  };
  const double v = kuiperStatistic(a, b);
  EXPECT_NEAR(kuiperStatistic(turned(a, 0.3), turned(b, 0.3)), v, 1e-12);
  EXPECT_NEAR(kuiperStatistic(turned(a, 0.77), turned(b, 0.77)), v, 1e-12);
  EXPECT_GT(v, 0.9);
  EXPECT_GE(v, ksStatistic(a, b));
  EXPECT_DOUBLE_EQ(kuiperStatistic({0.1, 0.2}, {0.1, 0.2}), 0);
  EXPECT_DOUBLE_EQ(kuiperStatistic({}, {1}), 1);
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

TEST(DistributionDistance, QuantilesAndCdfOfASample) {
  EXPECT_DOUBLE_EQ(quantileOfSorted({1, 2, 3, 5}, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(quantileOfSorted({1, 2, 3, 5}, 1.0), 5);
  EXPECT_EQ(empiricalCdfAt({3, 1, 2, 2}, {0, 2, 2.5, 9}), (std::vector<double>{0, 0.75, 0.75, 1}));
}

// A 5-95 % percentile band of bootstrap CDFs holds the true CDF at a point about 90 % of the
// time: 400 samples of 150 exponential values, 200 resamples each, at the true quartiles. The
// binomial spread of 400 trials at 0.9 is 0.015; the percentile bootstrap of a CDF undercovers a
// little at this size, so the rate is asserted within [0.85, 0.95].
TEST(DistributionDistance, PercentileBandCoversATrueCdfAtItsNominalRate) {
  Rng rng(11);
  const std::vector<double> at{std::log(4.0 / 3.0), std::log(2.0), std::log(4.0)};
  const std::vector<double> truth{0.25, 0.5, 0.75};
  std::vector<int> covered(at.size(), 0);
  const int trials = 400;
  for (int t = 0; t < trials; ++t) {
    std::vector<double> sample(150), resample(150);
    for (double& v : sample) v = -std::log(1 - uniform01(rng));
    std::vector<std::vector<double>> curves;
    for (int b = 0; b < 200; ++b) {
      for (double& v : resample) v = sample[uniformIndex(rng, sample.size())];
      curves.push_back(empiricalCdfAt(resample, at));
    }
    const PercentileBand band = percentileBand(curves, 0.05, 0.95);
    for (std::size_t i = 0; i < at.size(); ++i)
      covered[i] += band.low[i] <= truth[i] && truth[i] <= band.high[i];
  }
  for (std::size_t i = 0; i < at.size(); ++i) {
    EXPECT_GT(covered[i], 0.85 * trials) << truth[i];
    EXPECT_LT(covered[i], 0.95 * trials) << truth[i];
  }
}

}  // namespace
}  // namespace solidtex
