#include <gtest/gtest.h>

#include <cstdint>

#include "common/Error.h"
#include "common/Grid.h"
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

}  // namespace
}  // namespace solidtex
