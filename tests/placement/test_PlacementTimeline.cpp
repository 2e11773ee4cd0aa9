#include <gtest/gtest.h>

#include "discStats.h"
#include "placement/PlacementTimeline.h"

namespace solidtex {
namespace {

TEST(PlacementTimeline, GivesTheTimeShareOfAFilledShareFromTheFirstParticle) {
  // The first sample is the first particle: the phase's start before it is left out.
  const PlacementTimeline timeline({{0.1, 5}, {0.1, 6}, {0.5, 7}, {1.0, 12}, {1.0, 13}});
  EXPECT_DOUBLE_EQ(timeline.timeShare(0.05), 0);
  EXPECT_DOUBLE_EQ(timeline.timeShare(0.1), 0);
  EXPECT_DOUBLE_EQ(timeline.timeShare(0.3), 0.125);
  EXPECT_DOUBLE_EQ(timeline.timeShare(0.5), 0.25);
  EXPECT_DOUBLE_EQ(timeline.timeShare(0.75), 0.5625);
  EXPECT_DOUBLE_EQ(timeline.timeShare(1.0), 1);
  EXPECT_DOUBLE_EQ(timeline.timeShare(1.2), 1);  // the large block may overshoot the small one
  EXPECT_DOUBLE_EQ(PlacementTimeline({}).timeShare(0.5), 0);
}

TEST(PlacementTimeline, IsTimedOnABlockOfAFewLargestParticlesAtMostATwentiethOfTheVolume) {
  // Gravel at one voxel per pixel: particles up to 71 voxels across, a margin of 36.
  EXPECT_EQ(timelineBlock({1096, 1096, 1096}, {1024, 1024, 1024}, 71), (Dims{213, 213, 213}));
  EXPECT_EQ(timelineBlock({2120, 2120, 328}, {2048, 2048, 256}, 71), (Dims{213, 213, 213}));
  EXPECT_EQ(timelineBlock({4168, 4168, 120}, {4096, 4096, 48}, 71), (Dims{213, 213, 48}));
  EXPECT_FALSE(timelineBlock({584, 584, 584}, {512, 512, 512}, 71));  // a seventh: not worth it
  // Small particles: a block of at least 192 voxels a side.
  EXPECT_EQ(timelineBlock({1048, 1048, 1048}, {1024, 1024, 1024}, 23), (Dims{192, 192, 192}));
  EXPECT_FALSE(timelineBlock({100, 100, 100}, {100, 100, 100}, 10));
}

TEST(PlacementTimeline, TimesAPlacementFromItsFirstParticleToItsEnd) {
  const ExemplarStats stats = test::discStats(test::kDiscs, 0.25);
  const ParticleFactory factory(stats, test::fewShapes());
  PlacementOptions options;
  options.dims = {64, 64, 64};
  options.counted = Box::at({8, 8, 8}, {48, 48, 48});
  options.voxelsPerPixel = 0.8;
  const PlacementTimeline timeline =
      timePlacement(stats, factory, PlacerKind::Edt, 20, options, {32, 40, 48});
  double last = 0;
  for (double filled = 0; filled <= 1.0; filled += 0.05) {
    const double share = timeline.timeShare(filled);
    EXPECT_GE(share, last);
    last = share;
  }
  EXPECT_DOUBLE_EQ(timeline.timeShare(0), 0);
  // How near timeShare(1) comes to 1 depends on the clock (a loaded machine stretches the last
  // particles' time): only the curve's shape is asserted.
  EXPECT_DOUBLE_EQ(timeline.timeShare(1.2), 1);
  EXPECT_GT(timeline.timeShare(0.9), 0);
  EXPECT_LT(timeline.timeShare(0.5), 1);
}

// The timed block has its own field and placer: the placement after it is the one without it.
TEST(PlacementTimeline, LeavesThePlacementAfterItAsItWas) {
  const ExemplarStats stats = test::discStats(test::kDiscs, 0.25);
  const ParticleFactory factory(stats, test::fewShapes());
  PlacementOptions options;
  options.dims = {48, 48, 48};
  options.voxelsPerPixel = 0.8;
  const auto place = [&] {
    const auto field = makeSpaciousnessField(PlacerKind::Edt, options.dims, 20);
    return placeLargestFirst(stats, factory, *field, options).ids;
  };
  const std::vector<std::int32_t> before = place();
  timePlacement(stats, factory, PlacerKind::Edt, 20, options, {40, 40, 40});
  EXPECT_EQ(place(), before);
}

}  // namespace
}  // namespace solidtex
