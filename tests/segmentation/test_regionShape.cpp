#include <cmath>
#include <numbers>
#include <tuple>

#include <gtest/gtest.h>

#include "common/Random.h"
#include "segmentation/regionShape.h"

namespace solidtex {
namespace {

// Pixels whose centres lie in the ellipse with semi-axes a, b turned by `angle`, centred at (100, 50)
// plus `shift` (a fraction of a pixel).
std::vector<cv::Point> digitalEllipse(double a, double b, double angle, cv::Point2d shift = {0, 0}) {
  std::vector<cv::Point> pixels;
  const int reach = int(std::ceil(std::max(a, b))) + 2;
  const double c = std::cos(angle), s = std::sin(angle);
  for (int y = -reach; y <= reach; ++y)
    for (int x = -reach; x <= reach; ++x) {
      const double dx = x - shift.x, dy = y - shift.y;
      const double u = (c * dx + s * dy) / a, v = (-s * dx + c * dy) / b;
      if (u * u + v * v <= 1) pixels.push_back({x + 100, y + 50});
    }
  return pixels;
}

// Digitisation errors depend on where the shape falls on the pixel grid: the measures are unbiased
// over random sub-pixel positions, as the sections of a solid fall.
struct Averages {
  double area = 0, perimeter = 0, roundness = 0, solidity = 1;
};
Averages averageOverShifts(double a, double b, double angle) {
  Rng rng(5);
  Averages m;
  constexpr int kShifts = 24;
  for (int i = 0; i < kShifts; ++i) {
    const RegionShape s =
        measureRegion(digitalEllipse(a, b, angle, {uniform01(rng) - 0.5, uniform01(rng) - 0.5}));
    m.area += s.area / kShifts;
    m.perimeter += s.perimeter / kShifts;
    m.roundness += s.roundness / kShifts;
    m.solidity = std::min(m.solidity, s.solidity);
  }
  return m;
}

double ramanujanPerimeter(double a, double b) {
  return std::numbers::pi * (3 * (a + b) - std::sqrt((3 * a + b) * (a + 3 * b)));
}

TEST(RegionShape, DigitalDiscsAreConvexAndRound) {
  for (double r : {5.0, 8.5, 14.0, 30.0}) {
    const Averages m = averageOverShifts(r, r, 0);
    EXPECT_NEAR(m.area / (std::numbers::pi * r * r), 1, 0.02) << r;
    EXPECT_NEAR(m.perimeter / (2 * std::numbers::pi * r), 1, 0.03) << r;
    EXPECT_NEAR(m.roundness, 1, 0.05) << r;
    EXPECT_GE(m.solidity, 0.95) << r;  // the contour's staircase dents a digital disc a little
  }
  const RegionShape centred = measureRegion(digitalEllipse(6, 6, 0));
  EXPECT_NEAR(centred.centroid.x, 100, 1e-9);
  EXPECT_NEAR(centred.centroid.y, 50, 1e-9);
}

TEST(RegionShape, DigitalEllipsesMatchTheirAnalyticRoundness) {
  for (const auto& [a, b, angle] : {std::tuple{16.0, 8.0, 0.0}, {20.0, 7.0, 0.5}, {24.0, 10.0, 1.2}}) {
    const Averages m = averageOverShifts(a, b, angle);
    const double p = ramanujanPerimeter(a, b);
    EXPECT_NEAR(m.perimeter / p, 1, 0.03) << a << ' ' << b;
    EXPECT_NEAR(m.roundness, 4 * std::numbers::pi * std::numbers::pi * a * b / (p * p), 0.05)
        << a << ' ' << b;
    EXPECT_GE(m.solidity, 0.95) << a << ' ' << b;
  }
}

// An L of two 10 x 30 bars: its contour through the boundary pixels' centres encloses 29^2 - 20^2 =
// 441 (plus half a pixel where the 8-connected contour cuts the inner corner), its convex hull (0,0)
// (9,0) (29,20) (29,29) (0,29) 29^2 - 20^2 / 2 = 641.
TEST(RegionShape, ConcaveRegionsHaveLowSolidity) {
  std::vector<cv::Point> pixels;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 30; ++x)
      if (x < 10 || y >= 20) pixels.push_back({x, y});
  const RegionShape s = measureRegion(pixels);
  EXPECT_EQ(s.area, 500);
  EXPECT_NEAR(s.solidity, 441.5 / 641.0, 1e-9);
  EXPECT_LT(s.roundness, 0.6);
}

// A digital ellipse's second moments are the ellipse's (a^2 / 4 and b^2 / 4) within a pixel's own
// 1/12: its aspect is b / a and its orientation its turn, on any sub-pixel position; a disc's is 1.
TEST(RegionShape, AspectAndOrientationOfEllipses) {
  Rng rng(7);
  for (const auto& [a, b, angle] : {std::tuple{20.0, 10.0, 0.5}, std::tuple{12.0, 4.0, 2.8},
                                    std::tuple{9.0, 9.0, 0.0}, std::tuple{30.0, 10.0, 1.5708}}) {
    const RegionShape s =
        measureRegion(digitalEllipse(a, b, angle, {uniform01(rng) - 0.5, uniform01(rng) - 0.5}));
    EXPECT_NEAR(s.aspect, b / a, 0.03) << a << ' ' << b;
    if (a > b) {
      EXPECT_NEAR(s.orientation, angle, 0.02) << a << ' ' << b;
    }
    EXPECT_GE(s.orientation, 0);
    EXPECT_LT(s.orientation, std::numbers::pi);
  }
  EXPECT_NEAR(measureRegion({{3, 4}}).aspect, 1, 1e-12);
}

TEST(RegionShape, OnePixel) {
  const RegionShape s = measureRegion({{3, 4}});
  EXPECT_EQ(s.area, 1);
  EXPECT_EQ(s.solidity, 1);
  EXPECT_GT(s.perimeter, 0);
}

}  // namespace
}  // namespace solidtex
