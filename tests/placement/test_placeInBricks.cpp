#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include <tbb/global_control.h>

#include "common/Error.h"
#include "discStats.h"
#include "placement/cropToCountedBox.h"
#include "placement/placeInBricks.h"
#include "placementChecks.h"

namespace solidtex {
namespace {

using test::discStats;
using test::expectConsistent;
using test::fewShapes;
using test::kDiscs;

constexpr double kVoxelsPerPixel = 0.8;
// The largest disc (21 pixels) at 0.8 voxels per pixel, as makeParticleSolid caps the fields: a
// halo of 16, so bricks of 32.
const float kRadiusCap = float(std::sqrt(3.0) * 21 * kVoxelsPerPixel / 2 + 1);

BrickedPlacementResult placeBricked(const ExemplarStats& stats, Dims dims, int edge, std::uint64_t seed = 1,
                                    std::optional<Box> counted = std::nullopt) {
  const ParticleFactory factory(stats, fewShapes());
  BrickedPlacementOptions options;
  options.placement.dims = dims;
  options.placement.counted = counted;
  options.placement.voxelsPerPixel = kVoxelsPerPixel;
  options.placement.seed = seed;
  options.radiusCap = kRadiusCap;
  options.brickEdge = edge;
  return placeInBricks(stats, factory, options);
}

// Ids of particles with voxels on both sides of the plane between x = at - 1 and x = at.
std::set<std::int32_t> idsAcrossX(const PlacementResult& r, int at) {
  std::set<std::int32_t> across;
  for (int z = 0; z < r.dims.z; ++z)
    for (int y = 0; y < r.dims.y; ++y) {
      const std::int32_t a = r.ids[r.dims.index(at - 1, y, z)], b = r.ids[r.dims.index(at, y, z)];
      if (a != 0 && a == b) across.insert(a);
    }
  return across;
}

// Bricks of 32 in a 64^3 volume: eight bricks, one per colour. Particles stay whole and apart
// across the bricks' faces, some run through them, and the volume reaches the photo's fraction.
TEST(PlaceInBricks, PlacesWholeSeparateParticlesThatRunThroughBrickFaces) {
  const ExemplarStats stats = discStats(kDiscs, 0.25);
  const BrickedPlacementResult bricked = placeBricked(stats, {64, 64, 64}, 32);
  const PlacementResult& r = bricked.placement;
  expectConsistent(r, stats);
  EXPECT_EQ(bricked.halo, 16);
  ASSERT_EQ(bricked.bricks.size(), 8u);
  std::set<int> colours;
  for (const BrickPlacement& b : bricked.bricks) {
    colours.insert(b.colour);
    // A brick's own particles reach the fraction, to half a particle; its box also holds its
    // neighbours' ends, and its particles' ends lie in theirs (a disc of 8 voxels' radius is 0.066
    // of a 32^3 brick).
    EXPECT_NEAR(b.volumeFraction, 0.25, 0.066) << b.stopReason;
    EXPECT_GT(b.particles, 0);
  }
  EXPECT_EQ(colours.size(), 8u);
  EXPECT_EQ(r.stopReason, "area fraction reached (8 of 8 bricks)");
  EXPECT_NEAR(r.volumeFraction, 0.25, 0.01);
  EXPECT_FALSE(idsAcrossX(r, 32).empty());
  EXPECT_EQ(bricked.colourSeconds.size(), 8u);
}

// Each brick draws from a seed of its own, and the bricks of a colour are joined in their order.
TEST(PlaceInBricks, IsTheSameAtAnyThreadCount) {
  const ExemplarStats stats = discStats(kDiscs, 0.2);
  const PlacementResult a = placeBricked(stats, {64, 48, 40}, 32, 7).placement;
  EXPECT_NE(a.ids, placeBricked(stats, {64, 48, 40}, 32, 8).placement.ids);
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(a.ids, placeBricked(stats, {64, 48, 40}, 32, 7).placement.ids);
}

// The open boundary's margin: the bricks tile the counted box, those on its faces also place from
// the margin, and the block cut out keeps the photo's fraction up to its faces.
TEST(PlaceInBricks, BricksOfACountedBoxPlaceIntoItsMarginToo) {
  const ExemplarStats stats = discStats(kDiscs, 0.25);
  const Box counted = Box::at({9, 9, 9}, {64, 64, 64});
  const BrickedPlacementResult bricked = placeBricked(stats, {82, 82, 82}, 32, 3, counted);
  const PlacementResult& whole = bricked.placement;
  ASSERT_EQ(whole.counted, counted);
  ASSERT_EQ(whole.ids.size(), counted.dims().count());
  EXPECT_EQ(bricked.bricks[7].brick, (Box{{32, 32, 32}, {64, 64, 64}}));
  const PlacementResult block = cropToCountedBox(whole);
  EXPECT_NEAR(block.volumeFraction, 0.25, 0.02);
  EXPECT_LT(block.particles.size(), whole.particles.size()) << "no particle was placed in the margin";
}

TEST(PlaceInBricks, RefusesBricksNarrowerThanTwoHalosOrOddAroundATorus) {
  const ExemplarStats stats = discStats(kDiscs, 0.2);
  EXPECT_THROW(placeBricked(stats, {64, 64, 64}, 24), InputError);
  const ParticleFactory factory(stats, fewShapes());
  BrickedPlacementOptions options;
  options.placement.dims = {96, 64, 64};  // three bricks of 32 along x: two of one colour would meet
  options.placement.periodic = true;
  options.radiusCap = kRadiusCap;
  options.brickEdge = 32;
  EXPECT_THROW(placeInBricks(stats, factory, options), InputError);
}

// A periodic volume in bricks: windows wrap around the torus, particles cross its faces whole, and
// none overlaps another across a face or a brick's.
TEST(PlaceInBricks, APeriodicVolumeWrapsItsBricks) {
  const ExemplarStats stats = discStats(kDiscs, 0.25);
  const ParticleFactory factory(stats, fewShapes());
  BrickedPlacementOptions options;
  options.placement.dims = {64, 64, 64};
  options.placement.periodic = true;
  options.placement.voxelsPerPixel = kVoxelsPerPixel;
  options.radiusCap = kRadiusCap;
  options.brickEdge = 32;
  const PlacementResult r = placeInBricks(stats, factory, options).placement;
  EXPECT_TRUE(r.periodic);
  ASSERT_EQ(r.ids.size(), r.dims.count());
  std::vector<std::size_t> voxels(r.particles.size() + 1, 0);
  for (const std::int32_t id : r.ids) ++voxels[std::size_t(id)];
  for (const PlacedParticle& p : r.particles) EXPECT_EQ(voxels[std::size_t(p.id)], p.voxelCount) << p.id;
  // Each brick ends within about half a particle of its share, and a particle here is up to 6 % of
  // a brick: eight bricks are 0.02 from the fraction at worst.
  EXPECT_NEAR(r.volumeFraction, 0.25, 0.02);
  EXPECT_FALSE(idsAcrossX(r, 32).empty());
  std::set<std::int32_t> acrossTheFace;  // the same particle at x = 63 and x = 0
  for (int z = 0; z < r.dims.z; ++z)
    for (int y = 0; y < r.dims.y; ++y) {
      const std::int32_t a = r.ids[r.dims.index(63, y, z)];
      if (a != 0 && a == r.ids[r.dims.index(0, y, z)]) acrossTheFace.insert(a);
    }
  EXPECT_FALSE(acrossTheFace.empty());
}

// Spots only inside the box asked for: every particle's centre is there (discs' hulls hold their
// centre, and the shape's anchor is its voxel nearest the centre).
TEST(PlaceLargestFirstBricks, ParticlesAreCentredInTheSpotsBox) {
  const ExemplarStats stats = discStats(kDiscs, 0.3);
  const ParticleFactory factory(stats, fewShapes());
  const Dims dims{56, 56, 56};
  const auto field = makeSpaciousnessField(PlacerKind::Edt, dims, kRadiusCap);
  PlacementOptions options;
  options.dims = dims;
  options.voxelsPerPixel = kVoxelsPerPixel;
  options.spots = Box{{16, 16, 16}, {40, 40, 40}};
  options.counted = options.spots;
  options.idsEverywhere = true;
  const PlacementResult r = placeLargestFirst(stats, factory, *field, options);
  ASSERT_EQ(r.ids.size(), dims.count());
  ASSERT_FALSE(r.particles.empty());
  for (const PlacedParticle& p : r.particles) {
    const double centre[3] = {p.origin.x + p.box.x / 2.0, p.origin.y + p.box.y / 2.0,
                              p.origin.z + p.box.z / 2.0};
    for (const double c : centre) {
      EXPECT_GE(c, 16 - 1.5);
      EXPECT_LE(c, 40 + 1.5);
    }
  }
  EXPECT_GE(r.volumeFraction, 0.3);
}

// Obstacles take their voxels from the start and count toward the fraction: a slab of a third of
// the target leaves two thirds to place, around it.
TEST(PlaceLargestFirstBricks, ObstaclesAreAvoidedAndCounted) {
  const ExemplarStats stats = discStats(kDiscs, 0.3);
  const ParticleFactory factory(stats, fewShapes());
  const Dims dims{40, 40, 40};
  PlacementObstacle slab;
  slab.bin = 9;
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) slab.voxels.push_back({x, y, z});
  slab.voxelCount = slab.voxels.size();
  PlacementOptions options;
  options.dims = dims;
  options.voxelsPerPixel = kVoxelsPerPixel;
  options.obstacles = {slab};
  const auto field = makeSpaciousnessField(PlacerKind::Edt, dims, kRadiusCap);
  const PlacementResult r = placeLargestFirst(stats, factory, *field, options);
  std::size_t own = 0;
  for (const PlacedParticle& p : r.particles) {
    own += p.voxelCount;
    EXPECT_GE(p.origin.z, 4) << "particle " << p.id << " overlaps the slab";
  }
  const double slabFraction = double(slab.voxels.size()) / double(dims.count());
  EXPECT_NEAR(r.volumeFraction, 0.3, 0.02);
  EXPECT_NEAR(double(own) / double(dims.count()), 0.3 - slabFraction, 0.02);
}

}  // namespace
}  // namespace solidtex
