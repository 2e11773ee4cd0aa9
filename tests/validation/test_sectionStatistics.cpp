#include <cmath>
#include <numbers>
#include <numeric>

#include <gtest/gtest.h>

#include "common/distributionDistance.h"
#include "validation/sectionStatistics.h"

namespace solidtex {
namespace {

std::vector<std::int32_t> sphereVolume(const Dims& dims, double radius) {
  std::vector<std::int32_t> ids(dims.count(), 0);
  const double c = (dims.x - 1) * 0.5;
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i)
        if ((i - c) * (i - c) + (j - c) * (j - c) + (k - c) * (k - c) <= radius * radius)
          ids[dims.index(i, j, k)] = 1;
  return ids;
}

// Planes at a uniform distance h in [0, r] from a sphere's centre cut discs of area pi (r^2 - h^2).
// Those of at least area a0 have h <= h0 = sqrt(r^2 - a0/pi), on average pi (r^2 - h0^2/3).
TEST(SectionStatistics, SphereSectionsHaveTheExactMeanArea) {
  const Dims dims{64, 64, 64};
  const double r = 12;
  SectionOptions options;
  options.offsetsPerAxis = 64;
  options.obliquePlanes = 600;
  options.minArea = 20;
  const SectionStatistics s = sampleSections(dims, sphereVolume(dims, r), options);
  ASSERT_GT(s.areas.size(), 300u);
  const double mean = std::accumulate(s.areas.begin(), s.areas.end(), 0.0) / double(s.areas.size());
  const double h0Squared = r * r - options.minArea / std::numbers::pi;
  EXPECT_NEAR(mean / (std::numbers::pi * (r * r - h0Squared / 3)), 1.0, 0.05);
  for (double a : s.areas) EXPECT_LE(a, std::numbers::pi * (r + 1) * (r + 1));
}

TEST(SectionStatistics, AreaFractionOfAHalfFilledVolume) {
  const Dims dims{32, 32, 32};
  std::vector<std::int32_t> ids(dims.count(), 0);
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i) ids[dims.index(i, j, k)] = 1;
  SectionOptions options;
  options.obliquePlanes = 0;
  const SectionStatistics s = sampleSections(dims, ids, options);
  EXPECT_EQ(s.planes, 48);
  EXPECT_NEAR(s.areaFraction, 0.5, 1e-9);
  EXPECT_TRUE(s.areas.empty());  // the half-space touches every window's edge
}

TEST(DistributionDistance, KolmogorovSmirnov) {
  EXPECT_DOUBLE_EQ(ksStatistic({1, 2, 3}, {3, 2, 1}), 0);
  EXPECT_DOUBLE_EQ(ksStatistic({1, 2}, {5, 6}), 1);
  EXPECT_DOUBLE_EQ(ksStatistic({1, 2, 3, 4}, {3, 4, 5, 6}), 0.5);
}

TEST(DistributionDistance, WassersteinOfAShiftIsTheShift) {
  EXPECT_NEAR(wasserstein1({1, 2, 3}, {1.5, 2.5, 3.5}), 0.5, 1e-12);
  EXPECT_NEAR(wasserstein1({0, 0, 0, 4}, {1, 1, 1, 1}), 1.5, 1e-12);  // 3*1 + 3 over 4 atoms
  EXPECT_DOUBLE_EQ(wasserstein1({2, 7}, {7, 2}), 0);
}

}  // namespace
}  // namespace solidtex
