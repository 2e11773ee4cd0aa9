#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include "common/Error.h"
#include "common/bricksOf.h"
#include "io/BrickedVdb.h"
#include "io/vdbIO.h"
#include "tests/scratchPath.h"

namespace solidtex {
namespace {

namespace fs = std::filesystem;

// Every voxel different, with all the grids a volume synthesis writes: a brick put one voxel off
// or a grid left out shows.
SolidVolume gradientSolid(const Dims& dims) {
  SolidVolume v;
  v.dims = dims;
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        v.color.push_back({float(i) / float(dims.x), float(j) / float(dims.y), float(k) / float(dims.z)});
        v.sourceVoxel.push_back({float(k), float(i), float(j)});
      }
  return v;
}

SolidVolume boxOf(const SolidVolume& whole, const Box& box) {
  SolidVolume part;
  part.dims = box.dims();
  part.origin = box.lo;
  for (int k = box.lo.z; k < box.hi.z; ++k)
    for (int j = box.lo.y; j < box.hi.y; ++j)
      for (int i = box.lo.x; i < box.hi.x; ++i) {
        part.color.push_back(whole.color[whole.dims.index(i, j, k)]);
        part.sourceVoxel.push_back(whole.sourceVoxel[whole.dims.index(i, j, k)]);
      }
  return part;
}

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

const std::map<std::string, std::string> kMetadata = {{"seed", "5"}, {"command_line", "x"}};

// Bricks on OpenVDB's 8-voxel leaves and across them (12), added in any order, some through
// another process's bytes: the file writeVdb gives for the whole volume.
TEST(BrickedVdb, BricksInAnyOrderWriteTheWholeVolumesFile) {
  const Dims dims{40, 24, 16};
  SolidVolume whole = gradientSolid(dims);
  const fs::path expected = test::scratchPath("bricked", "whole.vdb");
  whole.metadata = kMetadata;
  writeVdb(expected.string(), whole);
  for (const int edge : {8, 12}) {
    std::vector<Box> bricks = bricksOf(dims, edge);
    std::reverse(bricks.begin(), bricks.end());
    BrickedVdb mine, other;
    for (std::size_t b = 0; b < bricks.size(); ++b) (b % 3 == 1 ? other : mine).add(boxOf(whole, bricks[b]));
    mine.addBytes(other.bytes());
    const fs::path path = test::scratchPath("bricked", "bricks" + std::to_string(edge) + ".vdb");
    mine.write(path.string(), kMetadata);
    EXPECT_TRUE(fileBytes(path) == fileBytes(expected)) << "bricks of " << edge;
    fs::remove(path);
  }
  fs::remove(expected);
}

TEST(BrickedVdb, ADenseBoxIsThoseVoxels) {
  const Dims dims{24, 16, 16};
  const SolidVolume whole = gradientSolid(dims);
  BrickedVdb bricks;
  for (const Box& b : bricksOf(dims, 8)) bricks.add(boxOf(whole, b));
  const Box box{{3, 5, 7}, {20, 9, 16}};
  const SolidVolume dense = bricks.denseBox(box);
  EXPECT_EQ(dense.dims, box.dims());
  EXPECT_EQ(dense.origin, box.lo);
  EXPECT_TRUE(dense.color == boxOf(whole, box).color);
}

TEST(BrickedVdb, BytesThatAreNoStreamAreRefused) {
  BrickedVdb bricks;
  EXPECT_THROW(bricks.addBytes("not a vdb stream"), InputError);
}

// A region keeps the whole volume's index space: its trees join others' by index.
TEST(BrickedVdb, ARegionsVoxelsKeepTheirIndexInTheWhole) {
  SolidVolume region = gradientSolid({4, 3, 2});
  region.origin = {40, 8, 16};
  const fs::path path = test::scratchPath("bricked", "region.vdb");
  writeVdb(path.string(), region, 0.5);
  openvdb::initialize();
  openvdb::io::File file(path.string());
  file.open();
  const auto grid = file.readGrid("color");
  file.close();
  EXPECT_EQ(grid->evalActiveVoxelBoundingBox(),
            openvdb::CoordBBox(openvdb::Coord(40, 8, 16), openvdb::Coord(43, 10, 17)));
  EXPECT_EQ(grid->indexToWorld(openvdb::Coord(40, 8, 16)), openvdb::Vec3d(20, 4, 8));
  const SolidVolume read = readVdb(path.string());
  EXPECT_EQ(read.dims, region.dims);
  EXPECT_TRUE(read.color == region.color);
  fs::remove(path);
}

}  // namespace
}  // namespace solidtex
