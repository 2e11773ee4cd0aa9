#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "common/Error.h"
#include "common/Grid.h"
#include "common/bricksOf.h"
#include "common/memoryBudget.h"

namespace solidtex {
namespace {

// Indices and counts stay exact past 2^31 and 2^32 voxels (PoreSpy's porosity went wrong above 2^31
// from an int32 count): the last voxel of a 2048^3 volume is voxel 2^33 - 1.
TEST(Dims, CountsAndIndexesPast32Bits) {
  const Dims dims{2048, 2048, 2048};
  EXPECT_EQ(dims.count(), std::size_t(1) << 33);
  const Voxel last{2047, 2047, 2047}, past31{5, 0, 512}, past32{7, 3, 1024};
  EXPECT_EQ(dims.index(last), (std::size_t(1) << 33) - 1);
  EXPECT_EQ(dims.index(past31), (std::size_t(1) << 31) + 5);
  EXPECT_EQ(dims.index(past32), (std::size_t(1) << 32) + 3 * 2048 + 7);
  for (const Voxel& v : {last, past31, past32}) EXPECT_EQ(dims.voxel(dims.index(v)), v);
}

// Placement indexes voxels with 32 bits: a volume of more voxels is refused, by size, before any of it
// is allocated; one of more than 2^31 is not.
TEST(Dims, VolumesBeyond32BitIndicesAreRefusedUpFront) {
  EXPECT_THROW(requireVolumeBytes("the volume", {2048, 2048, 1025}, 1.0), OptionError);
  EXPECT_NO_THROW(requireVolumeBytes("the volume", {2048, 2048, 520}, 1.0));  // 2.18 G voxels
}

TEST(Bricks, TileTheVolumeOnceInAFixedOrder) {
  const Dims dims{10, 7, 5};
  const std::vector<Box> bricks = bricksOf(dims, 4);
  ASSERT_EQ(bricks.size(), 3u * 2u * 2u);
  EXPECT_EQ(bricks[0], (Box{{0, 0, 0}, {4, 4, 4}}));
  EXPECT_EQ(bricks[1], (Box{{4, 0, 0}, {8, 4, 4}}));
  EXPECT_EQ(bricks.back(), (Box{{8, 4, 4}, {10, 7, 5}}));
  std::vector<int> covered(dims.count(), 0);
  for (const Box& b : bricks)
    for (int z = b.lo.z; z < b.hi.z; ++z)
      for (int y = b.lo.y; y < b.hi.y; ++y)
        for (int x = b.lo.x; x < b.hi.x; ++x) ++covered[dims.index(x, y, z)];
  EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int c) { return c == 1; }));
  EXPECT_EQ(bricksOf(dims, 0), std::vector<Box>{Box::of(dims)});
}

}  // namespace
}  // namespace solidtex
