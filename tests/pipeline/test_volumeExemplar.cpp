#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include "common/Error.h"
#include "pipeline/synthesizeVolumeJob.h"

namespace solidtex {
namespace {

namespace fs = std::filesystem;

fs::path writeDensity(const std::string& name, const openvdb::FloatGrid::Ptr& grid) {
  grid->setName("density");
  const fs::path path = fs::temp_directory_path() / ("solidtex_exemplar_" + name + ".vdb");
  openvdb::io::File(path.string()).write({grid});
  return path;
}

// Two voxels 300 apart make a 301^3 exemplar that is empty: refused at once, naming the box.
TEST(VolumeExemplar, AMostlyEmptyBoxIsRefused) {
  openvdb::initialize();
  auto grid = openvdb::FloatGrid::create(0.f);
  grid->tree().setValue(openvdb::Coord(0, 0, 0), 0.5f);
  grid->tree().setValue(openvdb::Coord(300, 300, 300), 0.5f);
  const fs::path sparse = writeDensity("sparse", grid);
  try {
    readVolumeExemplar(sparse.string());
    ADD_FAILURE() << "two voxels in a 301^3 box were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("301x301x301 box; crop it"), std::string::npos) << e.what();
  }
  fs::remove(sparse);
}

TEST(VolumeExemplar, ADenseBoxIsRead) {
  openvdb::initialize();
  auto grid = openvdb::FloatGrid::create(0.f);
  grid->denseFill(openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(7)), 0.25f, /*active=*/true);
  const fs::path path = writeDensity("dense", grid);
  const DenseVolume exemplar = readVolumeExemplar(path.string());
  EXPECT_EQ(exemplar.dims, (Dims{8, 8, 8}));
  EXPECT_EQ(exemplar.channels, 1);
  fs::remove(path);
}

}  // namespace
}  // namespace solidtex
