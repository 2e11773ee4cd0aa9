#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "phaseFixtures.h"
#include "validation/minkowskiFunctionals.h"

namespace solidtex {
namespace {

using testing::fieldWhere;

double sq(double v) { return v * v; }

PhaseField ball(int n, double r) {
  const double c = 0.5 * (n - 1) + 0.3;  // off the lattice's symmetry
  return fieldWhere({n, n, n},
                    [&](double x, double y, double z) { return sq(x - c) + sq(y - c) + sq(z - c) <= r * r; });
}

PhaseField torus(double big, double small) {
  return fieldWhere({48, 48, 24}, [&](double x, double y, double z) {
    const double ring = std::hypot(x - 23.5, y - 23.5) - big;
    return ring * ring + sq(z - 11.5) <= small * small;
  });
}

TEST(EulerCharacteristic, IsExactForSpheresToriShellsAndACubeWithAHole) {
  for (Connectivity c : {Connectivity::Vertices, Connectivity::Faces}) {
    EXPECT_EQ(eulerCharacteristic(ball(24, 8), c), 1);
    EXPECT_EQ(eulerCharacteristic(torus(14, 5), c), 0);
    const PhaseField shell = fieldWhere({30, 30, 30}, [](double x, double y, double z) {
      const double d = std::sqrt(sq(x - 14.5) + sq(y - 14.5) + sq(z - 14.5));
      return d <= 12 && d >= 8;
    });
    EXPECT_EQ(eulerCharacteristic(shell, c), 2);
    const PhaseField holed = fieldWhere({20, 20, 20}, [](double x, double y, double z) {
      const bool cube = x >= 2 && x < 18 && y >= 2 && y < 18 && z >= 2 && z < 18;
      return cube && !(x >= 7 && x < 13 && y >= 7 && y < 13);
    });
    EXPECT_EQ(eulerCharacteristic(holed, c), 0);
  }
  // Two cubes that share only an edge: one body with 26-neighbours, two with 6.
  const PhaseField edgeTouching = fieldWhere({6, 6, 3}, [](double x, double y, double z) {
    return z == 1 && ((x < 3 && y < 3) || (x >= 3 && y >= 3));
  });
  EXPECT_EQ(eulerCharacteristic(edgeTouching, Connectivity::Vertices), 1);
  EXPECT_EQ(eulerCharacteristic(edgeTouching, Connectivity::Faces), 2);
}

TEST(EulerCharacteristic, OfImagesCountsComponentsLessHoles) {
  const PhaseField rings = fieldWhere({40, 20, 1}, [](double x, double y, double) {
    const double d = std::hypot(x - 9.5, y - 9.5), e = std::hypot(x - 29.5, y - 9.5);
    return (d <= 8 && d >= 4) || e <= 6;
  });
  EXPECT_EQ(eulerCharacteristic(rings, Connectivity::Vertices), 1);  // an annulus (0) and a disc (1)
  EXPECT_EQ(eulerCharacteristic(rings, Connectivity::Faces), 1);
}

TEST(MinkowskiDensities, SurfaceAndMeanCurvatureOfADigitalBall) {
  const double r = 20;
  const PhaseField b = ball(56, r);
  const double volume = double(b.dims.count());
  for (bool periodic : {true, false}) {
    const MinkowskiDensities m = minkowskiDensities(b, periodic);
    EXPECT_NEAR(m.fraction * volume, 4.0 / 3.0 * std::numbers::pi * r * r * r, 0.01 * r * r * r);
    const double windows = periodic ? volume : std::pow(55.0, 3);
    EXPECT_NEAR(m.euler * windows, 1.0, 1e-9);  // the ball's cells are in every window they could be
    if (!periodic) continue;                    // lines end at the faces: a stationary density
    EXPECT_NEAR(m.boundary * volume / (4 * std::numbers::pi * r * r), 1.0, 0.03);
    EXPECT_NEAR(m.meanCurvature * volume / (4 * std::numbers::pi * r), 1.0, 0.05);
  }
}

// The surface density of a Boolean model of balls: S_V = lambda S exp(-lambda V) (Ohser &
// Muecklich 2000, 5.3). Its M_V and chi_V are not asserted: the digital union joins balls that
// nearly touch, which lowers them well beyond the sampling spread (docs/validation.md).
TEST(MinkowskiDensities, SurfaceMatchesTheBooleanBallModel) {
  double lambda = 0;
  const double R = 10, pi = std::numbers::pi;
  PhaseField balls = testing::booleanBallsMatrix(128, R, 0.6, 11, &lambda);
  for (auto& v : balls.inside) v = !v;
  const double q = std::exp(-lambda * 4.0 / 3.0 * pi * R * R * R);  // of the points drawn
  const MinkowskiDensities m = minkowskiDensities(balls, true);
  EXPECT_NEAR(m.fraction, 1 - q, 0.01);
  EXPECT_NEAR(m.boundary / (lambda * 4 * pi * R * R * q), 1.0, 0.03);
}

TEST(MinkowskiDensities, PerimeterOfADigitalDisc) {
  const double r = 30;
  const PhaseField disc = fieldWhere(
      {80, 80, 1}, [&](double x, double y, double) { return sq(x - 39.7) + sq(y - 40.2) <= r * r; });
  const MinkowskiDensities m = minkowskiDensities(disc, true);
  EXPECT_NEAR(m.boundary * 6400 / (2 * std::numbers::pi * r), 1.0, 0.03);
  EXPECT_NEAR(m.euler * 6400, 1.0, 1e-9);
  EXPECT_EQ(m.meanCurvature, 0.0);
}

}  // namespace
}  // namespace solidtex
