#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "common/Error.h"
#include "common/ThreadLimit.h"
#include "io/vdbIO.h"
#include "pipeline/compareJob.h"
#include "pipeline/particleSolidJob.h"
#include "tests/scratchPath.h"
#include "validation/sectionStatistics.h"

namespace solidtex {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) { return test::scratchPath("pipeline_test", name); }

ParticleSolidJob jobFor(const std::string& exemplar, int size, const fs::path& output) {
  ParticleSolidJob job;
  job.photo = std::string(SOLIDTEX_DATA_DIR) + "/particles/" + exemplar + ".png";
  job.output = output.string();
  job.dims = {size, size, size};
  job.progress = false;
  return job;
}

// 6-connected pieces per particle id, by one flood fill over the whole volume.
std::map<std::int32_t, int> piecesPerId(const SolidVolume& volume) {
  const Dims& dims = volume.dims;
  std::vector<std::uint8_t> seen(dims.count(), 0);
  std::vector<std::size_t> stack;
  std::map<std::int32_t, int> pieces;
  for (std::size_t start = 0; start < dims.count(); ++start) {
    const std::int32_t id = volume.particleId[start];
    if (id == 0 || seen[start]) continue;
    ++pieces[id];
    seen[start] = 1;
    stack.assign(1, start);
    while (!stack.empty()) {
      const Voxel v = dims.voxel(stack.back());
      stack.pop_back();
      const int step[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
      for (const auto& s : step) {
        if (!dims.contains(v.x + s[0], v.y + s[1], v.z + s[2])) continue;
        const std::size_t n = dims.index(v.x + s[0], v.y + s[1], v.z + s[2]);
        if (!seen[n] && volume.particleId[n] == id) {
          seen[n] = 1;
          stack.push_back(n);
        }
      }
    }
  }
  return pieces;
}

// Ids of the particles with a voxel on a face of the volume.
std::set<std::int32_t> idsOnFaces(const SolidVolume& volume) {
  const Dims& d = volume.dims;
  std::set<std::int32_t> ids;
  for (int z = 0; z < d.z; ++z)
    for (int y = 0; y < d.y; ++y)
      for (int x = 0; x < d.x; ++x)
        if (x == 0 || y == 0 || z == 0 || x == d.x - 1 || y == d.y - 1 || z == d.z - 1)
          if (const std::int32_t id = volume.particleId[d.index(x, y, z)]; id > 0) ids.insert(id);
  return ids;
}

std::string bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class ParticleSolidOfExemplar : public testing::TestWithParam<std::string> {};

// Whole particles (those the faces cut, as any block cut out of a larger solid, may fall apart in
// pieces), the photo's area fraction in the volume and on its sections (or a stated reason).
TEST_P(ParticleSolidOfExemplar, GivesWholeParticlesAtThePhotosAreaFraction) {
  const fs::path output = scratch(GetParam() + ".vdb");
  const nlohmann::json report = runParticleSolid(jobFor(GetParam(), 64, output));
  const SolidVolume volume = readVdb(output.string());
  ASSERT_EQ(volume.dims, (Dims{64, 64, 64}));

  const std::map<std::int32_t, int> pieces = piecesPerId(volume);
  EXPECT_EQ(pieces.size(), report["volume"]["particles"].get<std::size_t>());
  const std::set<std::int32_t> cut = idsOnFaces(volume);
  EXPECT_FALSE(cut.empty());
  for (const auto& [id, count] : pieces) {
    if (!cut.count(id)) {
      EXPECT_EQ(count, 1) << "particle " << id << " is in pieces";
    }
  }

  std::size_t occupied = 0;
  for (std::size_t i = 0; i < volume.particleId.size(); ++i) {
    occupied += volume.particleId[i] > 0;
    ASSERT_EQ(volume.density[i], volume.particleId[i] > 0 ? 1.f : 0.f);
  }
  const double volumeFraction = double(occupied) / double(volume.dims.count());
  EXPECT_DOUBLE_EQ(volumeFraction, report["volume"]["volume_fraction"].get<double>());
  const double areaFraction = report["photo"]["area_fraction"].get<double>();
  if (report["volume"]["stop_reason"] == "area fraction reached") {
    EXPECT_NEAR(volumeFraction, areaFraction, 0.02);
    SectionOptions sections;
    sections.offsetsPerAxis = 64;
    sections.obliquePlanes = 0;
    // Every axis plane together holds every voxel once per axis: the sections' fraction is the volume's.
    EXPECT_NEAR(sampleSections(volume.dims, volume.particleId, sections).areaFraction, volumeFraction, 1e-9);
  } else {
    EXPECT_LT(volumeFraction, areaFraction);
    EXPECT_NE(report["volume"]["stop_reason"].get<std::string>().find("no bin fits"), std::string::npos);
  }
  fs::remove(output);
}

INSTANTIATE_TEST_SUITE_P(Bundled, ParticleSolidOfExemplar,
                         testing::Values("smarties", "coins", "gravel", "leopard"));

// Section sizing makes the solid's sections look more like the photo's particles than the paper's
// box sizing does, at the same area fraction.
TEST(ParticleSolidJob, SectionSizingBringsSectionAreasCloserToThePhotos) {
  std::map<Sizing, nlohmann::json> comparison;
  for (const Sizing sizing : {Sizing::Bbox, Sizing::Sections}) {
    const fs::path output = scratch(std::string("coins-") + sizingName(sizing) + ".vdb");
    ParticleSolidJob job = jobFor("coins", 96, output);
    job.sizing = sizing;
    runParticleSolid(job);
    CompareJob compare;
    compare.photo = job.photo;
    compare.volume = output.string();
    comparison[sizing] = runCompare(compare);
    EXPECT_NEAR(comparison[sizing]["volume_fraction"].get<double>(),
                comparison[sizing]["area_fraction"].get<double>(), 0.02);
    fs::remove(output);
  }
  EXPECT_LT(comparison[Sizing::Sections]["ks"].get<double>(),
            comparison[Sizing::Bbox]["ks"].get<double>() - 0.1);
  EXPECT_LT(comparison[Sizing::Sections]["wasserstein1_over_mean"].get<double>(),
            comparison[Sizing::Bbox]["wasserstein1_over_mean"].get<double>());
}

TEST(ParticleSolidJob, SameSeedGivesTheSameBytesWithOneAndTwoThreads) {
  const fs::path one = scratch("one.vdb"), two = scratch("two.vdb"), other = scratch("other.vdb");
  const fs::path oneMeshes = scratch("one.ply"), twoMeshes = scratch("two.ply");
  {
    const ThreadLimit limit(1);
    ParticleSolidJob job = jobFor("coins", 48, one);
    job.meshPath = oneMeshes.string();
    runParticleSolid(job);
  }
  {
    const ThreadLimit limit(2);
    ParticleSolidJob job = jobFor("coins", 48, two);
    job.meshPath = twoMeshes.string();
    runParticleSolid(job);
    ParticleSolidJob seed2 = jobFor("coins", 48, other);
    seed2.seed = 2;
    runParticleSolid(seed2);
  }
  EXPECT_EQ(bytesOf(one), bytesOf(two));
  EXPECT_EQ(bytesOf(oneMeshes), bytesOf(twoMeshes));
  EXPECT_NE(bytesOf(one), bytesOf(other));
  for (const auto& path : {one, two, other, oneMeshes, twoMeshes}) fs::remove(path);
}

// The xy photo given again for the xz and yz planes is the one-photo solid, byte for byte; a
// different photo for them makes another (aligned) solid.
TEST(ParticleSolidJob, ThreeIdenticalPhotosGiveTheOnePhotoSolid) {
  const fs::path one = scratch("one_photo.vdb"), three = scratch("three_photos.vdb"),
                 other = scratch("other_planes.vdb");
  runParticleSolid(jobFor("coins", 32, one));
  ParticleSolidJob same = jobFor("coins", 32, three);
  same.photoXz = same.photoYz = same.photo;
  runParticleSolid(same);
  ParticleSolidJob planes = jobFor("coins", 32, other);
  planes.photoXz = std::string(SOLIDTEX_DATA_DIR) + "/particles/smarties.png";
  runParticleSolid(planes);
  EXPECT_EQ(bytesOf(one), bytesOf(three));
  EXPECT_NE(bytesOf(one), bytesOf(other));
  for (const auto& path : {one, three, other}) fs::remove(path);
}

TEST(ParticleSolidJob, BadInputLeavesNoOutputFile) {
  const fs::path output = scratch("bad.vdb");
  fs::remove(output);
  ParticleSolidJob zero = jobFor("coins", 0, output);
  EXPECT_THROW(runParticleSolid(zero), InputError);
  ParticleSolidJob absurd = jobFor("coins", kMaxVolumeEdge + 1, output);
  EXPECT_THROW(runParticleSolid(absurd), InputError);
  ParticleSolidJob missing = jobFor("no-such-photo", 32, output);
  EXPECT_THROW(runParticleSolid(missing), InputError);
  EXPECT_FALSE(fs::exists(output));
  ParticleSolidJob missingPlane = jobFor("coins", 32, output);
  missingPlane.photoYz = "no-such-photo.png";
  EXPECT_THROW(runParticleSolid(missingPlane), InputError);
  ParticleSolidJob maskedPlanes = jobFor("coins", 32, output);
  maskedPlanes.photoXz = std::string(SOLIDTEX_DATA_DIR) + "/particles/smarties.png";
  maskedPlanes.segmentation.maskPath = maskedPlanes.photo;
  EXPECT_THROW(runParticleSolid(maskedPlanes), InputError);
  EXPECT_FALSE(fs::exists(output));
  ParticleSolidJob phasedPlanes = jobFor("coins", 32, output);
  phasedPlanes.photoXz = std::string(SOLIDTEX_DATA_DIR) + "/particles/smarties.png";
  phasedPlanes.phases.phases = 2;
  EXPECT_THROW(runParticleSolid(phasedPlanes), InputError);
  // The photo itself as a phase mask: its particles show more colours than two phases.
  ParticleSolidJob crowdedMask = jobFor("smarties", 32, output);
  crowdedMask.phases = {2, crowdedMask.photo};
  EXPECT_THROW(runParticleSolid(crowdedMask), InputError);
  ParticleSolidJob noPhases = jobFor("coins", 32, output);
  noPhases.phases.phases = -1;
  EXPECT_THROW(runParticleSolid(noPhases), InputError);
  EXPECT_FALSE(fs::exists(output));
  ParticleSolidJob unwritable = jobFor("coins", 32, "/proc/solidtex/out.vdb");
  EXPECT_THROW(runParticleSolid(unwritable), InputError);
}

}  // namespace
}  // namespace solidtex
