#include <cmath>
#include <numbers>
#include <numeric>

#include <gtest/gtest.h>

#include "common/Error.h"
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

// Boxes 12 x 6 x 3 along x, y, z: the planes of one axis cut only its sections, each of the
// box's own proportions (aspect 0.5 in xy and yz, 0.25 in xz), major axis along the image's x.
TEST(SectionStatistics, PlaneAxisCutsOnlyThatPlane) {
  const Dims dims{64, 64, 64};
  std::vector<std::int32_t> ids(dims.count(), 0);
  std::int32_t id = 0;
  for (int k = 4; k + 3 < 60; k += 10)
    for (int j = 4; j + 6 < 60; j += 12)
      for (int i = 4; i + 12 < 60; i += 18) {
        ++id;
        for (int z = k; z < k + 3; ++z)
          for (int y = j; y < j + 6; ++y)
            for (int x = i; x < i + 12; ++x) ids[dims.index(x, y, z)] = id;
      }
  const std::pair<const char*, double> planes[] = {{"yz", 0.5}, {"xz", 0.25}, {"xy", 0.5}};
  for (const auto& [name, aspect] : planes) {
    SectionOptions options;
    options.offsetsPerAxis = 64;
    options.obliquePlanes = 0;
    options.shapeMinArea = 10;
    options.planeAxis = planeAxisOf(name);
    const SectionStatistics s = sampleSections(dims, ids, options);
    EXPECT_EQ(s.planes, 64) << name;
    ASSERT_FALSE(s.shapes.empty()) << name;
    for (const RegionShape& shape : s.shapes) {
      EXPECT_NEAR(shape.aspect, aspect, 0.03) << name;
      EXPECT_NEAR(shape.orientation, 0, 1e-9) << name;
    }
  }
  EXPECT_THROW(planeAxisOf("zx"), InputError);
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
