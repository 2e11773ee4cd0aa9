#include <gtest/gtest.h>

#include "phaseFixtures.h"
#include "validation/localThickness.h"

namespace solidtex {
namespace {

TEST(LocalThickness, EveryVoxelOfABallHasItsRadius) {
  const PhaseField ball = testing::fieldWhere({41, 41, 41}, [](double x, double y, double z) {
    return (x - 20) * (x - 20) + (y - 20) * (y - 20) + (z - 20) * (z - 20) <= 15.0 * 15.0;
  });
  const LocalThickness t = localThickness(ball);
  ASSERT_FALSE(t.sizes.empty());
  EXPECT_NEAR(t.sizes.front(), 15.0, 1.0);  // the centre's distance to the first voxel outside
  EXPECT_NEAR(t.cumulative.front(), 1.0, 1e-12);
  for (std::size_t i = 0; i < ball.inside.size(); ++i)
    EXPECT_EQ(t.radius[i], ball.inside[i] ? float(t.sizes.front()) : 0.0f);
}

TEST(LocalThickness, TwoBallsSplitTheCurveByTheirVolumes) {
  const auto inBall = [](double x, double y, double z, double cx, double r) {
    return (x - cx) * (x - cx) + (y - 20) * (y - 20) + (z - 20) * (z - 20) <= r * r;
  };
  const PhaseField balls = testing::fieldWhere({64, 41, 41}, [&](double x, double y, double z) {
    return inBall(x, y, z, 18, 14) || inBall(x, y, z, 50, 6);
  });
  const LocalThickness t = localThickness(balls, {40});
  std::size_t big = 0, all = 0;
  for (std::size_t i = 0; i < balls.inside.size(); ++i) {
    all += balls.inside[i];
    big += balls.inside[i] && balls.dims.voxel(i).x < 34;
  }
  // Radii above the small ball's depth cover the big ball alone, all of it; the smallest covers all.
  for (std::size_t s = 0; s < t.sizes.size(); ++s) {
    if (t.sizes[s] > 7.0) {
      EXPECT_NEAR(t.cumulative[s], double(big) / double(all), 1e-12) << t.sizes[s];
    }
    if (s > 0) {
      EXPECT_GE(t.cumulative[s], t.cumulative[s - 1]);
    }
  }
  EXPECT_NEAR(t.sizes.back(), 1.0, 1e-12);
  EXPECT_NEAR(t.cumulative.back(), 1.0, 1e-12);
}

TEST(LocalThickness, InAnImageIsTheLargestInscribedDisc) {
  // A 9-pixel-wide strip: every pixel lies in a disc of radius 5 (depth to the first pixel outside).
  const PhaseField strip =
      testing::fieldWhere({60, 30, 1}, [](double, double y, double) { return y >= 10 && y < 19; });
  const LocalThickness t = localThickness(strip, {10});
  EXPECT_NEAR(t.sizes.front(), 5.0, 1e-9);
  EXPECT_NEAR(t.cumulative.front(), 1.0, 1e-12);
}

}  // namespace
}  // namespace solidtex
