#include <array>
#include <stdexcept>

#include <gtest/gtest.h>

#include "particles/rotation.h"
#include "particles/visualHull.h"
#include "particles/voxelizeHull.h"
#include "shapes.h"

namespace solidtex {
namespace {

HullMesh gravelHull(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Silhouette> views;
  for (int i = 0; i < 3; ++i) {
    const auto contour = test::gravelContour(rng, 15 + 10 * uniform01(rng));
    views.push_back({normalizeContour(contour, 48), randomRotation(rng)});
  }
  return visualHull(views);
}

HullMesh unitCube() {
  const std::vector<Eigen::Vector2d> square{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  return visualHull({{square, Eigen::Matrix3d::Identity()}});
}

// Face layers that no voxel centre reached are cut off: a sharp tip of a gravel hull may miss a few
// voxel centres in a row, but the tips hold little of a side.
TEST(Voxelize, EveryBoxIsTightWithinTheAskedOneAndOnePiece) {
  const int sizes[][3] = {{1, 1, 1},   {1, 3, 2},  {2, 2, 2},    {3, 17, 5},
                          {40, 10, 5}, {1, 30, 1}, {25, 25, 25}, {9, 60, 33}};
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const HullMesh hull = gravelHull(seed);
    ASSERT_FALSE(hull.triangles.empty());
    Rng rng(seed + 100);
    for (const auto& s : sizes) {
      const VoxelShape shape = voxelize(hull, randomRotation(rng), s[0], s[1], s[2]);
      const int sides[3] = {shape.dims.x, shape.dims.y, shape.dims.z};
      for (int a = 0; a < 3; ++a) {
        EXPECT_LE(sides[a], s[a]);
        EXPECT_GE(sides[a], std::max(1, int(0.85 * s[a]) - 1));
      }
      ASSERT_EQ(shape.inside.size(), shape.dims.count());
      EXPECT_TRUE(test::tightInBox(shape))
          << "seed " << seed << " box " << s[0] << "x" << s[1] << "x" << s[2];
      EXPECT_EQ(test::firstPieceSize(shape), shape.voxelCount()) << "seed " << seed;
    }
  }
}

TEST(Voxelize, VoxelCountMatchesTheScaledMeshVolume) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const HullMesh hull = gravelHull(seed);
    Rng rng(seed);
    const Eigen::Matrix3d rotation = randomRotation(rng);
    HullMesh turned = hull;
    for (auto& v : turned.vertices) v = rotation * v;
    const Eigen::Vector3d extent = turned.boxMax() - turned.boxMin();
    const Dims dims{50, 40, 60};
    const double expected = turned.volume() * dims.x * dims.y * dims.z / extent.prod();
    const VoxelShape shape = voxelize(hull, rotation, dims.x, dims.y, dims.z);
    EXPECT_NEAR(double(shape.voxelCount()) / expected, 1.0, 0.02) << "seed " << seed;
  }
}

TEST(Voxelize, CubeFillsItsBoxWhateverTheSize) {
  const HullMesh cube = unitCube();
  for (const auto& s : {std::array{1, 1, 1}, std::array{3, 3, 3}, std::array{7, 1, 20}}) {
    const VoxelShape shape = voxelize(cube, Eigen::Matrix3d::Identity(), s[0], s[1], s[2]);
    EXPECT_EQ(shape.voxelCount(), shape.dims.count());
  }
}

TEST(Voxelize, IsDeterministic) {
  const HullMesh hull = gravelHull(3);
  Rng a(5), b(5);
  EXPECT_EQ(voxelize(hull, randomRotation(a), 20, 21, 22).inside,
            voxelize(hull, randomRotation(b), 20, 21, 22).inside);
}

TEST(Voxelize, RejectsBadSizesAndEmptyHulls) {
  const HullMesh cube = unitCube();
  EXPECT_THROW(voxelize(cube, Eigen::Matrix3d::Identity(), 0, 5, 5), std::invalid_argument);
  EXPECT_THROW(voxelize(cube, Eigen::Matrix3d::Identity(), 5, -1, 5), std::invalid_argument);
  EXPECT_THROW(voxelize(cube, Eigen::Matrix3d::Identity(), 5, 5, kMaxParticleSide + 1),
               std::invalid_argument);
  EXPECT_THROW(voxelize(HullMesh{}, Eigen::Matrix3d::Identity(), 5, 5, 5), std::invalid_argument);
}

TEST(VoxelShape, BoundaryIsTheShell) {
  const HullMesh cube = unitCube();
  EXPECT_EQ(voxelize(cube, Eigen::Matrix3d::Identity(), 3, 3, 3).boundary().size(), 26u);
  EXPECT_EQ(voxelize(cube, Eigen::Matrix3d::Identity(), 5, 5, 5).boundary().size(), 125u - 27u);
  EXPECT_EQ(voxelize(cube, Eigen::Matrix3d::Identity(), 1, 1, 1).boundary(), (std::vector<Voxel>{{0, 0, 0}}));
}

}  // namespace
}  // namespace solidtex
