#include <cmath>

#include <gtest/gtest.h>

#include "phaseFixtures.h"
#include "validation/twoPointCorrelation.h"

namespace solidtex {
namespace {

// S2 of the matrix of a Boolean model of balls of radius R: exp(-lambda |union of two balls r
// apart|) = p^(1 + 3r/4R - r^3/16R^3) for r < 2R, p^2 beyond (Torquato 2002, eq. 4.29 form).
double booleanMatrixS2(double r, double R, double p) {
  if (r >= 2 * R) return p * p;
  return std::pow(p, 1 + 3 * r / (4 * R) - r * r * r / (16 * R * R * R));
}

TEST(TwoPointCorrelation, MatchesTheBooleanBallModelInEveryDirection) {
  double intensity = 0;
  const double R = 6, p = 0.6;
  const PhaseField matrix = testing::booleanBallsMatrix(96, R, p, 7, &intensity);
  for (bool periodic : {true, false}) {
    const CorrelationCurves s2 = twoPointCorrelation(matrix, {24, periodic});
    const double phi = s2.phaseFraction;
    // One realisation's fraction is off its expectation by sampling; compare in its own terms.
    ASSERT_NEAR(phi, p, 0.02);
    ASSERT_EQ(s2.radial.size(), 25u);
    EXPECT_NEAR(s2.radial[0], phi, 1e-9);
    for (int r = 1; r <= 24; ++r) {
      const double expected = booleanMatrixS2(r, R, phi);
      EXPECT_NEAR(s2.radial[std::size_t(r)], expected, 0.012) << "r " << r << " periodic " << periodic;
      for (const auto& axis : s2.axes) EXPECT_NEAR(axis[std::size_t(r)], expected, 0.02) << "r " << r;
    }
    double lo = 0, hi = 2 * R;  // where the model's excess over phi^2 falls to 1/e of phi - phi^2
    for (int step = 0; step < 60; ++step) {
      const double mid = 0.5 * (lo + hi);
      (booleanMatrixS2(mid, R, phi) - phi * phi > (phi - phi * phi) / std::exp(1.0) ? lo : hi) = mid;
    }
    EXPECT_NEAR(s2.correlationLength, lo, 0.25);
  }
}

TEST(TwoPointCorrelation, ZeroPaddingNormalisesByTheOverlap) {
  // Stripes 3 on, 5 off along x: S2 along x is exact for any r once normalised by the overlap count.
  const PhaseField stripes =
      testing::fieldWhere({40, 24, 1}, [](double x, double, double) { return int(x) % 8 < 3; });
  const CorrelationCurves s2 = twoPointCorrelation(stripes, {16, false});
  EXPECT_TRUE(s2.axes[2].empty());
  for (int r = 0; r <= 16; ++r) {
    int pairs = 0, both = 0;
    for (int x = 0; x + r < 40; ++x) ++pairs, both += (x % 8 < 3) && ((x + r) % 8 < 3);
    EXPECT_NEAR(s2.axes[0][std::size_t(r)], double(both) / pairs, 1e-9) << r;
    EXPECT_NEAR(s2.axes[1][std::size_t(r)], 3.0 / 8, 1e-9) << r;
  }
}

TEST(TwoPointClusterFunction, CountsPairsInTheSameParticleOnly) {
  // Two touching 4-voxel bars along x with different labels: same-label pairs only inside a bar.
  const Dims dims{8, 1, 1};
  const std::vector<std::int32_t> labels{1, 1, 1, 1, 2, 2, 2, 2};
  const CorrelationCurves c2 = twoPointClusterFunction(dims, labels, 5);
  ASSERT_EQ(c2.axes[0].size(), 6u);
  for (int r = 0; r <= 5; ++r)
    EXPECT_NEAR(c2.axes[0][std::size_t(r)], 2.0 * std::max(0, 4 - r) / (8 - r), 1e-12);
  EXPECT_NEAR(c2.phaseFraction, 1.0, 1e-12);
}

TEST(CurveDistance, IsTheRootMeanSquareDifference) {
  EXPECT_NEAR(curveDistance({1, 2, 3}, {1, 2, 3, 9}), 0.0, 1e-12);
  EXPECT_NEAR(curveDistance({0, 0}, {3, 4}), std::sqrt(12.5), 1e-12);
}

}  // namespace
}  // namespace solidtex
