#include <gtest/gtest.h>

#include "voxel/slice.h"

namespace solidtex {
namespace {

TEST(Slice, AxisPlaneReadsTheRightVoxels) {
  const Dims dims{4, 3, 2};
  std::vector<int> field(dims.count());
  for (std::size_t i = 0; i < field.size(); ++i) field[i] = int(i);
  const SlicePlane z1 = axisPlane(dims, 2, 1);
  ASSERT_EQ(z1.width, 4);
  ASSERT_EQ(z1.height, 3);
  const auto s = slice(dims, field, z1, -1);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_EQ(s[std::size_t(r * 4 + c)], int(dims.index(c, r, 1)));
  const SlicePlane x2 = axisPlane(dims, 0, 2);  // image x along y, image y along z
  EXPECT_EQ(x2.width, 3);
  EXPECT_EQ(x2.height, 2);
  EXPECT_EQ(slice(dims, field, x2, -1)[std::size_t(1 * 3 + 2)], int(dims.index(2, 2, 1)));
}

TEST(Slice, ObliquePlaneStaysInsideAndIsOrthonormal) {
  const Dims dims{32, 32, 32};
  const Eigen::Vector3d centre(15.5, 15.5, 15.5);
  const SlicePlane p = obliquePlane(dims, Eigen::Vector3d(1, 2, 3), centre);
  EXPECT_NEAR(p.u.norm(), 1, 1e-12);
  EXPECT_NEAR(p.v.norm(), 1, 1e-12);
  EXPECT_NEAR(p.u.dot(p.v), 0, 1e-12);
  EXPECT_NEAR(p.u.dot(Eigen::Vector3d(1, 2, 3)), 0, 1e-12);
  EXPECT_GT(p.width, 16);  // a usefully large window
  std::vector<int> field(dims.count(), 1);
  for (int value : slice(dims, field, p, 0)) EXPECT_EQ(value, 1);  // no sample falls outside
}

}  // namespace
}  // namespace solidtex
