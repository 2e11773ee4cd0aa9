#include <gtest/gtest.h>

#include "common/Error.h"
#include "placement/cropToCountedBox.h"
#include "placement/wholeParticleVolumes.h"

namespace solidtex {
namespace {

// Cubes placed by hand in a 20^3 placement whose counted box is [5, 15)^3: one with its centre on
// the box's lower corner (kept whole though the faces cut it to 2^3 of its 4^3), one cut by the box
// with its centre outside (left out), one inside, one far outside.
PlacementResult handPlaced() {
  PlacementResult p;
  p.dims = {20, 20, 20};
  p.counted = Box{{5, 5, 5}, {15, 15, 15}};
  const auto cube = [&](Voxel origin, int side) {
    PlacedParticle c;
    c.id = int(p.particles.size()) + 1;
    c.origin = origin;
    c.box = {side, side, side};
    c.voxelCount = std::size_t(side * side * side);
    p.particles.push_back(c);
  };
  cube({3, 3, 3}, 4);    // centre (5, 5, 5): on the box's corner
  cube({12, 13, 8}, 5);  // centre (14.5, 15.5, 10.5): outside, 3 x 2 x 5 of it inside
  cube({8, 8, 8}, 3);    // inside
  cube({0, 16, 0}, 2);   // outside
  const Dims d = p.counted.dims();
  p.ids.assign(d.count(), 0);
  for (const PlacedParticle& c : p.particles)
    for (int z = c.origin.z; z < c.origin.z + c.box.z; ++z)
      for (int y = c.origin.y; y < c.origin.y + c.box.y; ++y)
        for (int x = c.origin.x; x < c.origin.x + c.box.x; ++x)
          if (p.counted.contains({x, y, z})) p.ids[d.index(x - 5, y - 5, z - 5)] = c.id;
  return p;
}

TEST(WholeParticleVolumes, KeepsTheParticlesCentredInTheBlockWithAllTheirVoxels) {
  const PlacementResult placement = handPlaced();
  const WholeParticleVolumes whole = wholeParticleVolumes(placement);
  EXPECT_EQ(whole.volumes, (std::vector<double>{64, 27}));
  EXPECT_EQ(whole.cutParticles, 1u);
  EXPECT_DOUBLE_EQ(whole.cutShare, (64.0 - 8.0) / (64.0 + 27.0));
  // What the block itself keeps of the same particles: the faces' cut.
  const PlacementResult crop = cropToCountedBox(placement);
  ASSERT_EQ(crop.particles.size(), 3u);
  EXPECT_EQ(crop.particles[0].voxelCount, 8u);
  EXPECT_EQ(crop.particles[1].voxelCount, 30u);
}

TEST(WholeParticleVolumes, KeepEveryParticleOfAPeriodicPlacement) {
  PlacementResult placement = handPlaced();
  placement.periodic = true;
  placement.counted = Box::of(placement.dims);
  placement.ids.assign(placement.dims.count(), 0);
  const WholeParticleVolumes whole = wholeParticleVolumes(placement);
  EXPECT_EQ(whole.volumes, (std::vector<double>{64, 125, 27, 8}));
  EXPECT_EQ(whole.cutShare, 0.0);
}

TEST(WholeParticleVolumes, TravelThroughMetadataAndRefuseTextThatIsNotCounts) {
  const WholeParticleVolumes whole = wholeParticleVolumes(handPlaced());
  std::map<std::string, std::string> metadata{{"seed", "1"}};
  EXPECT_FALSE(readWholeVolumesMetadata(metadata, "a.vdb"));
  addWholeVolumesMetadata(whole, metadata);
  const std::optional<WholeParticleVolumes> read = readWholeVolumesMetadata(metadata, "a.vdb");
  ASSERT_TRUE(read);
  EXPECT_EQ(read->volumes, whole.volumes);
  EXPECT_NEAR(read->cutShare, whole.cutShare, 1e-6);
  EXPECT_EQ(read->cutParticles, whole.cutParticles);
  for (const char* bad : {"64 x", "64 -3", "64 0"}) {
    metadata["particle_volumes"] = bad;
    EXPECT_THROW(readWholeVolumesMetadata(metadata, "a.vdb"), InputError) << bad;
  }
}

}  // namespace
}  // namespace solidtex
