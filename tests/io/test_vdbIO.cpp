#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <tbb/task_arena.h>

#include "common/Error.h"
#include "io/checkVdbLayout.h"
#include "io/detail/valuesChecksum.h"
#include "io/detail/vdbGrids.h"
#include "io/vdbIO.h"

namespace solidtex {
namespace {

namespace fs = std::filesystem;

SolidVolume smallParticleVolume() {
  SolidVolume v;
  v.dims = {5, 4, 3};
  v.density.assign(v.dims.count(), 0.f);
  v.particleId.assign(v.dims.count(), 0);
  v.color.assign(v.dims.count(), Rgb{0.f, 0.f, 0.f});  // black background must stay active
  const std::size_t inside = v.dims.index(2, 1, 1);
  v.density[inside] = 1.f;
  v.particleId[inside] = 7;
  v.color[inside] = {0.25f, 0.5f, 0.75f};
  v.metadata = {{"seed", "42"}, {"exemplar", "disc.png"}};
  return v;
}

fs::path tempPath(const std::string& name) { return fs::temp_directory_path() / ("solidtex_voxel_" + name); }

TEST(VdbIO, RoundTripKeepsGridsAndMetadata) {
  const auto path = tempPath("roundtrip.vdb");
  const SolidVolume v = smallParticleVolume();
  writeVdb(path.string(), v);
  const SolidVolume r = readVdb(path.string());
  EXPECT_EQ(r.dims, v.dims);
  EXPECT_EQ(r.density, v.density);
  EXPECT_EQ(r.particleId, v.particleId);
  EXPECT_EQ(r.color, v.color);
  EXPECT_EQ(r.metadata.at("seed"), "42");
  EXPECT_EQ(r.metadata.at("exemplar"), "disc.png");
  fs::remove(path);
}

// Rewrites a file's grids after `edit` (OpenVDB's writer with its own statistics off, so that
// edited bounds stay as set).
void editGrids(const fs::path& path, const std::function<void(openvdb::GridBase&)>& edit) {
  openvdb::initialize();
  openvdb::GridPtrVec grids;
  {
    openvdb::io::File file(path.string());
    file.open();
    grids = *file.getGrids();
  }
  for (const auto& grid : grids) edit(*grid);
  openvdb::io::File rewritten(path.string());
  rewritten.setGridStatsMetadataEnabled(false);
  rewritten.write(grids);
}

// Measures of particle ids read neither the colour nor the density; the box is still the whole
// volume's (here the colour's, the density being active at one voxel), from the grids' recorded
// bounds, or from their trees when a writer recorded none.
TEST(VdbIO, ReadsOnlyTheGridsAskedFor) {
  const auto path = tempPath("idsonly.vdb");
  const SolidVolume v = smallParticleVolume();
  writeVdb(path.string(), v);
  const SolidVolume ids = readVdb(path.string(), {.density = false, .color = false, .particleId = true});
  EXPECT_EQ(ids.dims, v.dims);
  EXPECT_EQ(ids.particleId, v.particleId);
  EXPECT_TRUE(ids.density.empty());
  EXPECT_TRUE(ids.color.empty());
  EXPECT_EQ(ids.metadata.at("seed"), "42");

  editGrids(path, [](openvdb::GridBase& grid) {
    grid.removeMeta(openvdb::GridBase::META_FILE_BBOX_MIN);
    grid.removeMeta(openvdb::GridBase::META_FILE_BBOX_MAX);
  });
  const SolidVolume unrecorded =
      readVdb(path.string(), {.density = false, .color = false, .particleId = true});
  EXPECT_EQ(unrecorded.dims, v.dims);
  EXPECT_EQ(unrecorded.particleId, v.particleId);
  fs::remove(path);
}

// Rewrites a file's grids with their recorded bounds set as given.
void recordBounds(const fs::path& path, const openvdb::Vec3i& lo, const openvdb::Vec3i& hi) {
  editGrids(path, [&](openvdb::GridBase& grid) {
    grid.insertMeta(openvdb::GridBase::META_FILE_BBOX_MIN, openvdb::Vec3IMetadata(lo));
    grid.insertMeta(openvdb::GridBase::META_FILE_BBOX_MAX, openvdb::Vec3IMetadata(hi));
  });
}

TEST(VdbIO, RecordedBoundsThatCannotBeTrustedAreRefusedOrPassedOver) {
  const auto path = tempPath("bounds.vdb");
  const SolidVolume v = smallParticleVolume();  // particle 7 at (2, 1, 1)
  const VdbReadOptions idsOnly{.density = false, .color = false, .particleId = true};
  writeVdb(path.string(), v);
  recordBounds(path, {0, 0, 0}, {1, 1, 1});  // edited: the ids lie outside
  EXPECT_THROW(readVdb(path.string(), idsOnly), InputError);
  EXPECT_EQ(readVdb(path.string()).dims, v.dims);  // the trees' own bounds
  writeVdb(path.string(), v);
  recordBounds(path, {4, 3, 2}, {0, 0, 0});  // inverted: no box, the trees are read
  EXPECT_EQ(readVdb(path.string(), idsOnly).dims, v.dims);
  writeVdb(path.string(), v);
  recordBounds(path, {-(1 << 30), -(1 << 30), 0}, {(1 << 30) - 1, (1 << 30) - 1, 3});  // overflows int32
  EXPECT_THROW(readVdb(path.string(), idsOnly), InputError);
  fs::remove(path);
}

// A foreign file whose ids reach beyond its density grid: read whole, as always, over the
// density's box; read by ids alone, refused (the ids could be dropped unseen).
TEST(VdbIO, IdsBeyondTheDensityAreCroppedByAWholeRead) {
  const auto path = tempPath("foreignids.vdb");
  openvdb::initialize();
  auto density = openvdb::FloatGrid::create(0.f);
  density->setName("density");
  density->tree().setValue(openvdb::Coord(0, 0, 0), 1.f);
  auto ids = openvdb::Int32Grid::create(0);
  ids->setName("particle_id");
  ids->tree().setValue(openvdb::Coord(0, 0, 0), 1);
  ids->tree().setValue(openvdb::Coord(3, 3, 3), 2);
  openvdb::io::File(path.string()).write({density, ids});
  const SolidVolume whole = readVdb(path.string());
  EXPECT_EQ(whole.dims, (Dims{1, 1, 1}));
  EXPECT_EQ(whole.particleId, std::vector<std::int32_t>{1});
  EXPECT_THROW(readVdb(path.string(), {.density = false, .color = false, .particleId = true}), InputError);
  fs::remove(path);
}

// Grids are built one slab of 8 z-layers at a time, each slab's whole pages handed back as it goes:
// several slabs, a short last one, and layers of more than a page each come back voxel for voxel.
TEST(VdbIO, RoundTripOfManySlabsIsExact) {
  const auto path = tempPath("slabs.vdb");
  SolidVolume v;
  v.dims = {67, 41, 21};  // 2747 voxels a layer: 11 KiB of ids, 32 KiB of colours
  v.density.assign(v.dims.count(), 0.f);
  v.particleId.assign(v.dims.count(), 0);
  v.color.resize(v.dims.count());
  for (std::size_t i = 0; i < v.dims.count(); ++i) {
    const bool inside = (i * 2654435761u) % 7 < 3;
    v.density[i] = inside ? 1.f : 0.f;
    v.particleId[i] = inside ? std::int32_t(1 + i % 97) : 0;
    v.color[i] = {float(i % 251) / 251.f, float(i % 13) / 13.f, inside ? 1.f : 0.f};
  }
  writeVdb(path.string(), v);
  const SolidVolume r = readVdb(path.string());
  EXPECT_EQ(r.dims, v.dims);
  EXPECT_EQ(r.density, v.density);
  EXPECT_EQ(r.particleId, v.particleId);
  EXPECT_EQ(r.color, v.color);
  fs::remove(path);
}

TEST(VdbIO, FollowsTheOutputConventions) {
  const auto path = tempPath("conventions.vdb");
  writeVdb(path.string(), smallParticleVolume(), 0.5);
  openvdb::initialize();
  openvdb::io::File file(path.string());
  file.open();
  auto density = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("density"));
  auto color = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("color"));
  auto cd = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("Cd"));
  auto ids = openvdb::gridPtrCast<openvdb::Int32Grid>(file.readGrid("particle_id"));
  file.close();
  ASSERT_TRUE(density && color && cd && ids);
  EXPECT_EQ(density->getGridClass(), openvdb::GRID_FOG_VOLUME);
  EXPECT_EQ(density->activeVoxelCount(), 1u);        // 0 and inactive outside particles
  EXPECT_EQ(color->activeVoxelCount(), 5u * 4 * 3);  // colour over the whole box
  EXPECT_EQ(cd->activeVoxelCount(), color->activeVoxelCount());
  EXPECT_EQ(ids->tree().getValue(openvdb::Coord(2, 1, 1)), 7);
  EXPECT_DOUBLE_EQ(density->voxelSize()[0], 0.5);
  // Voxel (i,j,k) is centred at world (i,j,k) * voxel size.
  EXPECT_TRUE(density->indexToWorld(openvdb::Vec3d(2, 1, 1)).eq(openvdb::Vec3d(1.0, 0.5, 0.5)));
  fs::remove(path);
}

TEST(VdbIO, ContinuousSolidHasDensityOneEverywhere) {
  const auto path = tempPath("continuous.vdb");
  SolidVolume v;
  v.dims = {4, 4, 4};
  v.color.assign(v.dims.count(), Rgb{0.1f, 0.2f, 0.3f});
  writeVdb(path.string(), v);
  const SolidVolume r = readVdb(path.string());
  ASSERT_EQ(r.density.size(), v.dims.count());
  for (float d : r.density) EXPECT_EQ(d, 1.f);
  fs::remove(path);
}

TEST(VdbIO, ADensityOnlySolidKeepsItsBoxAndValues) {
  const auto path = tempPath("density.vdb");
  SolidVolume v;
  v.dims = {3, 2, 2};
  v.density = {0.f, 0.5f, 0.f, 0.25f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 0.f, 0.f};  // zeros on every face
  v.sourceVoxel.assign(v.dims.count(), {1.f, 2.f, 3.f});
  writeVdb(path.string(), v);
  const SolidVolume r = readVdb(path.string());
  EXPECT_EQ(r.dims, v.dims);
  EXPECT_TRUE(r.color.empty());
  EXPECT_EQ(r.density, v.density);
  fs::remove(path);
}

TEST(VdbIO, AVolumeThatStartsElsewhereIsReadFromItsFirstVoxel) {
  const auto path = tempPath("offset.vdb");
  openvdb::initialize();
  auto grid = openvdb::FloatGrid::create(0.f);
  grid->setName("density");
  grid->tree().setValue(openvdb::Coord(10, -4, 7), 0.5f);
  grid->tree().setValue(openvdb::Coord(11, -3, 7), 0.75f);
  openvdb::io::File(path.string()).write({grid});
  const SolidVolume r = readVdb(path.string());
  EXPECT_EQ(r.dims, (Dims{2, 2, 1}));
  ASSERT_EQ(r.density.size(), 4u);
  EXPECT_EQ(r.density[r.dims.index(0, 0, 0)], 0.5f);
  EXPECT_EQ(r.density[r.dims.index(1, 1, 0)], 0.75f);
  fs::remove(path);
}

// A volume read as cubes on its index axes: anything else must be refused, not silently distorted.
TEST(VdbIO, OnlyCubicAxisAlignedVoxelsAreRead) {
  using openvdb::math::Transform;
  openvdb::initialize();
  const auto path = tempPath("spacing.vdb");
  auto readWith = [&](const Transform::Ptr& transform) {
    auto grid = openvdb::FloatGrid::create(0.f);
    grid->setName("density");
    grid->setTransform(transform);
    grid->tree().setValue(openvdb::Coord(0, 0, 0), 0.5f);
    grid->tree().setValue(openvdb::Coord(1, 1, 1), 0.75f);
    openvdb::io::File(path.string()).write({grid});
    return readVdb(path.string());
  };
  auto uniform = Transform::createLinearTransform(0.25);
  uniform->postTranslate(openvdb::Vec3d(3, -2, 1));
  EXPECT_EQ(readWith(uniform).dims, (Dims{2, 2, 2}));
  const auto stretched =
      std::make_shared<Transform>(std::make_shared<openvdb::math::ScaleMap>(openvdb::Vec3d(1, 2, 0.5)));
  auto turned = Transform::createLinearTransform(1.0);
  turned->postRotate(0.3, openvdb::math::Z_AXIS);
  for (const auto& transform : {stretched, turned}) {
    try {
      readWith(transform);
      ADD_FAILURE() << transform->mapType() << " was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("resample it to cubic"), std::string::npos) << e.what();
    }
  }
  fs::remove(path);
}

TEST(VdbIO, UnwritablePathThrowsAndLeavesNothing) {
  const fs::path dir = tempPath("missing_folder");
  fs::remove_all(dir);
  EXPECT_THROW(writeVdb((dir / "out.vdb").string(), smallParticleVolume()), InputError);
  EXPECT_FALSE(fs::exists(dir));
}

TEST(VdbIO, ReadingAMissingOrCorruptFileThrows) {
  EXPECT_THROW(readVdb(tempPath("nope.vdb").string()), InputError);
  const auto path = tempPath("corrupt.vdb");
  { std::ofstream(path) << "not a vdb"; }
  EXPECT_THROW(readVdb(path.string()), InputError);
  fs::remove(path);
}

// checkVdbLayout walks each grid up to its root node's tiles, past a transform of each fixed-size
// map type: files with tiles and each such map must pass it and read back.
TEST(VdbLayout, RootTilesBehindEveryFixedSizeMapPass) {
  using openvdb::math::Transform;
  openvdb::initialize();
  openvdb::Mat4R sheared = openvdb::Mat4R::identity();
  sheared(0, 1) = 0.5;
  const std::vector<Transform::Ptr> transforms = {
      Transform::createLinearTransform(0.5), Transform::createLinearTransform(sheared),
      std::make_shared<Transform>(std::make_shared<openvdb::math::TranslationMap>(openvdb::Vec3d(1, 2, 3))),
      std::make_shared<Transform>(std::make_shared<openvdb::math::ScaleMap>(openvdb::Vec3d(1, 2, 3))),
      std::make_shared<Transform>(std::make_shared<openvdb::math::ScaleTranslateMap>(
          openvdb::Vec3d(1, 2, 3), openvdb::Vec3d(4, 5, 6)))};
  for (const auto& transform : transforms) {
    auto density = openvdb::FloatGrid::create(0.f);
    density->setName("density");
    density->setTransform(transform);
    density->tree().addTile(3, openvdb::Coord(0), 1.f, true);             // a root tile, active
    density->tree().addTile(3, openvdb::Coord(-4096, 0, 0), 2.f, false);  // and an inactive one
    density->tree().setValue(openvdb::Coord(9000, 1, 1), 3.f);
    auto ids = openvdb::Int32Grid::create(0);
    ids->setName("particle_id");
    ids->tree().addTile(3, openvdb::Coord(0, 4096, 0), 7, true);
    const auto path = tempPath("tiles.vdb");
    openvdb::io::File(path.string()).write({density, ids});
    EXPECT_EQ(checkVdbLayout(path.string()), (std::vector<long>{2, 1})) << transform->mapType();
    EXPECT_EQ(io::detail::readVdbGrids(path.string()).grids.size(), 2u) << transform->mapType();
    fs::remove(path);
  }
}

std::string bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(VdbGrids, WritingGroupByGroupGivesOpenVdbsOwnFile) {
  openvdb::initialize();
  auto color = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.f));
  color->setName("color");
  color->denseFill(openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(20, 9, 9)),
                   openvdb::Vec3s(0.5f, 0.25f, 1.f));
  auto cd = color->copyGrid();  // an instance: its tree is written once
  cd->setName("Cd");
  auto ids = openvdb::Int32Grid::create(0);
  ids->setName("particle_id");
  ids->tree().setValue(openvdb::Coord(3, 4, 5), 7);
  auto density = openvdb::FloatGrid::create(
      std::make_shared<openvdb::FloatTree>(ids->tree(), 0.f, 1.f, openvdb::TopologyCopy()));
  density->setName("density");
  openvdb::MetaMap meta;
  meta.insertMeta("seed", openvdb::StringMetadata("3"));

  const auto grouped = tempPath("grouped.vdb"), whole = tempPath("whole.vdb");
  io::detail::writeVdbGrids(grouped.string(),
                            {[&] {
                               return openvdb::GridPtrVec{color, cd};
                             },
                             [&] {
                               return openvdb::GridPtrVec{density, ids};
                             }},
                            meta);
  for (const auto& grid : openvdb::GridPtrVec{color, cd, density, ids})
    grid->insertMeta(io::detail::kValuesChecksumName,
                     openvdb::StringMetadata(io::detail::checksumText(*io::detail::valuesChecksum(*grid))));
  openvdb::io::File file(whole.string());
  file.setCompression(openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK);
  file.write(openvdb::GridPtrVec{color, cd, density, ids}, meta);
  // Byte for byte but the header's UUID (36 characters from byte 21), random in OpenVDB's file.
  std::string a = bytesOf(grouped), b = bytesOf(whole);
  ASSERT_EQ(a.size(), b.size());
  a.replace(21, 36, 36, '-');
  b.replace(21, 36, 36, '-');
  EXPECT_TRUE(a == b);
  const auto contents = io::detail::readVdbGrids(grouped.string());
  ASSERT_EQ(contents.grids.size(), 4u);
  EXPECT_EQ(contents.metadata->metaValue<std::string>("seed"), "3");
  fs::remove(grouped);
  fs::remove(whole);
}

// A colour that tells voxels and ids apart.
class CoordinateColoring final : public VolumeColoring {
public:
  Rgb at(int x, int y, int z, std::int32_t id) const override {
    return {float(x) / 256.f, float(y + id) / 256.f, float(z) / 256.f};
  }
};

// Colours painted leaf by leaf as they are written read back as the same colours written dense, over
// more than one batch of leaves and with leaves the box cuts.
TEST(VdbIO, ColoursPaintedWhileWritingAreTheColoursPaintedDense) {
  SolidVolume painted;
  painted.dims = {130, 130, 131};
  painted.particleId.resize(painted.dims.count());
  for (std::size_t i = 0; i < painted.particleId.size(); ++i) painted.particleId[i] = std::int32_t(i % 7);
  painted.coloring = std::make_shared<CoordinateColoring>();
  SolidVolume dense = painted;
  paintColor(dense);
  ASSERT_EQ(dense.color.size(), dense.dims.count());
  const auto paintedPath = tempPath("painted.vdb"), densePath = tempPath("dense.vdb");
  writeVdb(paintedPath.string(), painted);
  writeVdb(densePath.string(), dense);
  const SolidVolume a = readVdb(paintedPath.string()), b = readVdb(densePath.string());
  EXPECT_EQ(a.dims, b.dims);
  EXPECT_TRUE(a.color == b.color);
  EXPECT_EQ(a.particleId, b.particleId);
  EXPECT_EQ(a.activeVoxels, b.activeVoxels);
  fs::remove(paintedPath);
  fs::remove(densePath);
}

// A grid with many leaves and a tile, as copyFromDense makes of a volume with a constant block.
openvdb::FloatGrid::Ptr leavesAndATile() {
  auto grid = openvdb::FloatGrid::create(0.f);
  grid->setName("density");
  for (int i = 0; i < 4000; ++i)
    grid->tree().setValue(openvdb::Coord(i % 97, i % 89, i / 7), float(i) * 0.5f);
  grid->tree().addTile(/*level=*/1, openvdb::Coord(512, 0, 0), 3.f, /*active=*/true);
  return grid;
}

TEST(ValuesChecksum, SeesOneValueOneVoxelAndOneTileChange) {
  openvdb::initialize();
  const auto grid = leavesAndATile();
  const auto checksum = io::detail::valuesChecksum(*grid);
  ASSERT_TRUE(checksum);
  EXPECT_EQ(io::detail::valuesChecksum(*grid->deepCopy()), checksum);
  auto value = grid->deepCopy();
  value->tree().setValue(openvdb::Coord(5, 5, 0), 2.50001f);
  auto active = grid->deepCopy();
  active->tree().setValueOff(openvdb::Coord(5, 5, 0));
  auto tile = grid->deepCopy();
  tile->tree().addTile(1, openvdb::Coord(512, 0, 0), 3.5f, true);
  for (const auto& changed : {value, active, tile}) EXPECT_NE(io::detail::valuesChecksum(*changed), checksum);
  tbb::task_arena oneThread(1);
  oneThread.execute([&] { EXPECT_EQ(io::detail::valuesChecksum(*grid), checksum); });
  EXPECT_FALSE(io::detail::valuesChecksum(*openvdb::BoolGrid::create()));
}

// A grid whose values changed in a file solidtex wrote is refused, naming the grid: here the damage
// is made by OpenVDB's own writer with solidtex's UUID put back, in practice it is damage that still
// decodes. The same file with the UUID OpenVDB gave it was re-saved by another tool, its values
// perhaps edited on purpose, and is read.
TEST(VdbGrids, ValuesThatNoLongerMatchTheirChecksumAreRefused) {
  openvdb::initialize();
  const auto path = tempPath("checksum.vdb");
  io::detail::writeVdbGrids(path.string(), openvdb::GridPtrVec{leavesAndATile()});
  const std::string uuid = bytesOf(path).substr(21, 36);
  EXPECT_EQ(uuid[14], '8');  // version 8: solidtex's own
  auto read = io::detail::readVdbGrids(path.string());
  auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(read.grids.at(0));
  ASSERT_TRUE(grid->getMetadata<openvdb::StringMetadata>(io::detail::kValuesChecksumName));
  grid->tree().setValue(openvdb::Coord(1, 1, 0), -1.f);
  openvdb::io::File(path.string()).write(openvdb::GridPtrVec{grid});
  EXPECT_EQ(io::detail::readVdbGrids(path.string()).grids.size(), 1u);
  {
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(21);
    file.write(uuid.data(), std::streamsize(uuid.size()));
  }
  try {
    io::detail::readVdbGrids(path.string());
    ADD_FAILURE() << "changed values were read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("density grid do not match the checksum"), std::string::npos)
        << e.what();
  }
  fs::remove(path);
}

TEST(VdbGrids, AGridNameTwiceIsAProgrammingError) {
  auto a = openvdb::FloatGrid::create(), b = openvdb::FloatGrid::create();
  a->setName("density");
  b->setName("density");
  const auto path = tempPath("twice.vdb");
  EXPECT_THROW(io::detail::writeVdbGrids(path.string(), openvdb::GridPtrVec{a, b}), std::logic_error);
  fs::remove(path);
}

}  // namespace
}  // namespace solidtex
