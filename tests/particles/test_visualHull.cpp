#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "particles/rotation.h"
#include "particles/visualHull.h"
#include "particles/voxelizeHull.h"
#include "shapes.h"

namespace solidtex {
namespace {

using test::kPi;

// Frames whose third column (the viewing direction) is x, y or z; all proper rotations.
Eigen::Matrix3d lookAlong(int axis) {
  Eigen::Matrix3d r;
  r.col(0) = Eigen::Vector3d::Unit((axis + 1) % 3);
  r.col(1) = Eigen::Vector3d::Unit((axis + 2) % 3);
  r.col(2) = Eigen::Vector3d::Unit(axis);
  return r;
}

// A disc of diameter 1 as the 48-gon of the same area.
std::vector<Eigen::Vector2d> discPolygon() {
  const int n = 48;
  const double r = 0.5 * std::sqrt(2 * kPi / n / std::sin(2 * kPi / n));
  std::vector<Eigen::Vector2d> polygon;
  for (int i = 0; i < n; ++i)
    polygon.emplace_back(r * std::cos(2 * kPi * i / n), r * std::sin(2 * kPi * i / n));
  return polygon;
}

std::vector<Silhouette> discViews(const std::vector<Eigen::Matrix3d>& rotations,
                                  const std::vector<Eigen::Vector2d>& disc = discPolygon()) {
  std::vector<Silhouette> views;
  for (const Eigen::Matrix3d& r : rotations) views.push_back({disc, r});
  return views;
}

double tricylinderVolume(double r) { return 8 * (2 - std::sqrt(2.0)) * r * r * r; }

TEST(VisualHull, ThreeOrthogonalDiscsMakeTheTricylinder) {
  const HullMesh hull = visualHull(discViews({lookAlong(0), lookAlong(1), lookAlong(2)}));
  const double r = 20;  // the disc's radius in pixels = voxels; the unit cube is 2r voxels wide
  EXPECT_NEAR(hull.volume() * std::pow(2 * r, 3) / tricylinderVolume(r), 1.0, 0.03);
  const VoxelShape voxels = voxelize(hull, Eigen::Matrix3d::Identity(), 40, 40, 40);
  EXPECT_NEAR(double(voxels.voxelCount()) / tricylinderVolume(r), 1.0, 0.03);
}

TEST(VisualHull, MeshIsClosedOutwardAndASphereTopologically) {
  const HullMesh hull = visualHull(discViews({lookAlong(0), lookAlong(1), lookAlong(2)}));
  ASSERT_FALSE(hull.triangles.empty());
  EXPECT_TRUE(test::closedAndConsistent(hull));
  EXPECT_GT(hull.volume(), 0);  // outward: the divergence theorem gives the volume a positive sign
  const long faces = long(hull.triangles.size()), edges = 3 * faces / 2;
  EXPECT_EQ(long(hull.vertices.size()) - edges + faces, 2);
}

TEST(VisualHull, DiscsFromRandomDirectionsBoundTheSphere) {
  // Any number of views of a disc of radius r contains the ball of radius r, and any two views
  // at angle t bound it by the bicylinder, 16 r^3 / (3 sin t).
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    Rng rng(seed);
    std::vector<Eigen::Matrix3d> rotations;
    for (int i = 0; i < 3; ++i) rotations.push_back(randomRotation(rng));
    const HullMesh hull =
        visualHull(discViews(rotations, normalizeContour(test::ellipseContour(20, 20), 48)));
    ASSERT_TRUE(test::closedAndConsistent(hull));
    double upper = 1;  // the local cube
    for (int a = 0; a < 3; ++a)
      for (int b = a + 1; b < 3; ++b) {
        const double sine = rotations[a].col(2).cross(rotations[b].col(2)).norm();
        upper = std::min(upper, 16 * std::pow(0.5 * 1.02, 3) / (3 * sine));
      }
    const double lower = 4 * kPi / 3 * std::pow(0.5 * 0.97, 3);  // the polygon's inscribed disc
    EXPECT_GT(hull.volume(), lower) << "seed " << seed;
    EXPECT_LT(hull.volume(), upper) << "seed " << seed;
  }
}

TEST(VisualHull, SquaresAlongTheAxesMakeTheCube) {
  const std::vector<Eigen::Vector2d> square{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  const HullMesh hull = visualHull({{square, lookAlong(0)}, {square, lookAlong(1)}, {square, lookAlong(2)}});
  EXPECT_TRUE(test::closedAndConsistent(hull));
  EXPECT_NEAR(hull.volume(), 1.0, 1e-12);
  EXPECT_TRUE(hull.boxMin().isApprox(Eigen::Vector3d::Constant(-0.5)));
  EXPECT_TRUE(hull.boxMax().isApprox(Eigen::Vector3d::Constant(0.5)));
  const VoxelShape voxels = voxelize(hull, Eigen::Matrix3d::Identity(), 10, 12, 7);
  EXPECT_EQ(voxels.voxelCount(), 10u * 12u * 7u);
}

TEST(VisualHull, SquareFromAnAngleCutsTheCube) {
  // A square seen along z, turned 45 degrees about z: the cube minus its four vertical edges' wedges.
  const double s = 0.5;
  const std::vector<Eigen::Vector2d> diamond{
      {0, -s * std::sqrt(2.0)}, {s * std::sqrt(2.0), 0}, {0, s * std::sqrt(2.0)}, {-s * std::sqrt(2.0), 0}};
  const HullMesh hull = visualHull({{diamond, lookAlong(2)}});
  // 1e-5: prism corners snap to multiples of 2^-16
  EXPECT_NEAR(hull.volume(), 1.0 - 4 * (0.5 * std::pow(1 - std::sqrt(2.0) / 2, 2)), 1e-5);
}

TEST(VisualHull, DisjointViewsGiveNoHull) {
  const std::vector<Eigen::Vector2d> corner{{0.3, 0.3}, {0.5, 0.3}, {0.5, 0.5}, {0.3, 0.5}};
  const std::vector<Eigen::Vector2d> opposite{{-0.5, -0.5}, {-0.3, -0.5}, {-0.3, -0.3}, {-0.5, -0.3}};
  EXPECT_TRUE(visualHull({{corner, lookAlong(2)}, {opposite, lookAlong(2)}}).triangles.empty());
  EXPECT_TRUE(visualHull({{{}, lookAlong(2)}}).triangles.empty());
}

TEST(VisualHull, RejectsANonRotation) {
  const std::vector<Eigen::Vector2d> square{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  EXPECT_THROW(visualHull({{square, 2 * Eigen::Matrix3d::Identity()}}), std::invalid_argument);
  EXPECT_THROW(visualHull({{square, Eigen::Matrix3d(Eigen::Vector3d(1, 1, -1).asDiagonal())}}),
               std::invalid_argument);
}

TEST(VisualHull, NearlyTouchingPolygonStillMakesAValidHull) {
  // A slit from the top reaching within 1e-9 of the bottom edge: simple, but rounding the rotated
  // prism would make its walls cross unless the pinch is cut first.
  const std::vector<Eigen::Vector2d> slit{{-0.5, -0.5},     {0.5, -0.5},  {0.5, 0.5}, {0.01, 0.5},
                                          {0, -0.5 + 1e-9}, {-0.01, 0.5}, {-0.5, 0.5}};
  Rng rng(4);
  for (int i = 0; i < 10; ++i) {
    const HullMesh hull = visualHull({{slit, randomRotation(rng)}});
    ASSERT_FALSE(hull.triangles.empty());
    EXPECT_TRUE(test::closedAndConsistent(hull));
    EXPECT_GT(hull.volume(), 0.2);
  }
}

double area(const std::vector<Eigen::Vector2d>& poly) {
  double twice = 0;
  for (std::size_t i = 0; i < poly.size(); ++i)
    twice += poly[i].x() * poly[(i + 1) % poly.size()].y() - poly[i].y() * poly[(i + 1) % poly.size()].x();
  return twice / 2;
}

TEST(MakeSimplePolygon, CutsABowTieToItsLargerLoop) {
  // Edges (0,0)-(3,3) and (3,0)-(0,2) cross at (1.2,1.2); the right loop (area 2.7) beats the left (1.2).
  const std::vector<Eigen::Vector2d> bowTie{{0, 0}, {3, 3}, {3, 0}, {0, 2}};
  const auto simple = makeSimplePolygon(bowTie);
  ASSERT_EQ(simple.size(), 3u);
  EXPECT_GT(area(simple), 0);
  EXPECT_NEAR(area(simple), 0.5 * 3 * 1.8, 1e-12);
}

TEST(MakeSimplePolygon, CutsAPinchAndKeepsTheClearance) {
  const std::vector<Eigen::Vector2d> slit{{-0.5, -0.5},     {0.5, -0.5},  {0.5, 0.5}, {0.01, 0.5},
                                          {0, -0.5 + 1e-9}, {-0.01, 0.5}, {-0.5, 0.5}};
  const auto simple = makeSimplePolygon(slit);
  EXPECT_NEAR(area(simple), 0.5 * (1 - 0.01), 0.01);  // one half of the square
  for (std::size_t v = 0; v < simple.size(); ++v)
    for (std::size_t e = 0; e < simple.size(); ++e) {
      if (e == v || (e + 1) % simple.size() == v) continue;
      const Eigen::Vector2d a = simple[e], b = simple[(e + 1) % simple.size()];
      const double t = std::clamp((simple[v] - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      EXPECT_GE((simple[v] - (a + t * (b - a))).norm(), 1.0 / 1024) << v << " " << e;
    }
}

TEST(MakeSimplePolygon, OrientsCounterClockwiseAndDropsDegenerateVertices) {
  const std::vector<Eigen::Vector2d> clockwise{{0, 0}, {0, 1}, {0, 1},    {0.5, 1},
                                               {1, 1}, {1, 0}, {1, -0.5}, {1, 0}};
  const auto simple = makeSimplePolygon(clockwise);
  EXPECT_EQ(simple.size(), 4u);
  EXPECT_NEAR(area(simple), 1.0, 1e-12);
  EXPECT_TRUE(makeSimplePolygon({{0, 0}, {1, 1}, {2, 2}}).empty());
}

TEST(NormalizeContour, StretchesTheContourBoxToTheUnitSquare) {
  const auto poly = normalizeContour(test::ellipseContour(30, 8), 24);
  ASSERT_GE(poly.size(), 3u);
  EXPECT_LE(poly.size(), 24u);
  double lo[2] = {1, 1}, hi[2] = {-1, -1};
  for (const auto& p : poly)
    for (int a = 0; a < 2; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  for (int a = 0; a < 2; ++a) {
    EXPECT_GE(lo[a], -0.5);
    EXPECT_LE(hi[a], 0.5);
    EXPECT_GT(hi[a] - lo[a], 0.9);
  }
  EXPECT_NEAR(area(poly), kPi / 4, 0.05);  // an ellipse filling its box, however flat it was
  EXPECT_TRUE(normalizeContour({{0, 0}, {5, 0}, {9, 0}}, 24).empty());
}

}  // namespace
}  // namespace solidtex
