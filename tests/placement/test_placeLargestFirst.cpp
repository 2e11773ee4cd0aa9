#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include <tbb/global_control.h>

#include "common/Error.h"
#include "discStats.h"
#include "placement/cropToCountedBox.h"
#include "placement/placeLargestFirst.h"
#include "placementChecks.h"

namespace solidtex {
namespace {

using test::discStats;
using test::expectConsistent;
using test::fewShapes;
using test::kDiscs;

PlacementResult place(const ExemplarStats& stats, PlacerKind kind, Dims dims, std::uint64_t seed = 1,
                      double voxelsPerPixel = 0.8, bool periodic = false) {
  const ParticleFactory factory(stats, fewShapes());
  const auto field =
      makeSpaciousnessField(kind, dims, float(std::sqrt(3.0) * 21 * voxelsPerPixel / 2 + 1), periodic);
  PlacementOptions options;
  options.dims = dims;
  options.periodic = periodic;
  options.voxelsPerPixel = voxelsPerPixel;
  options.seed = seed;
  return placeLargestFirst(stats, factory, *field, options);
}

class PlaceLargestFirst : public testing::TestWithParam<PlacerKind> {};

TEST_P(PlaceLargestFirst, ReachesTheAreaFractionWithWholeSeparateParticles) {
  const ExemplarStats stats = discStats(kDiscs, 0.25);
  const PlacementResult r = place(stats, GetParam(), {40, 44, 48});
  expectConsistent(r, stats);
  EXPECT_EQ(r.stopReason, "area fraction reached");
  EXPECT_GE(r.volumeFraction, 0.25);
  std::size_t largest = 0;
  for (const PlacedParticle& p : r.particles) largest = std::max(largest, p.voxelCount);
  // Stops at the first particle past the target.
  EXPECT_LT(r.volumeFraction, 0.25 + double(largest) / double(r.dims.count()));
}

TEST_P(PlaceLargestFirst, SaysWhyWhenTheFractionCannotBeReached) {
  const ExemplarStats stats = discStats(kDiscs, 0.95);
  const PlacementResult r = place(stats, GetParam(), {24, 24, 24});
  expectConsistent(r, stats);
  EXPECT_EQ(r.stopReason.rfind("no bin fits any more (fraction ", 0), 0u) << r.stopReason;
  EXPECT_LT(r.volumeFraction, 0.95);
  EXPECT_GT(std::accumulate(r.rejectedPerBin.begin(), r.rejectedPerBin.end(), 0), 0);
}

TEST_P(PlaceLargestFirst, IsDeterministicForTheSeed) {
  const ExemplarStats stats = discStats(kDiscs, 0.2);
  const PlacementResult a = place(stats, GetParam(), {32, 32, 32}, 9);
  EXPECT_EQ(a.ids, place(stats, GetParam(), {32, 32, 32}, 9).ids);
  EXPECT_NE(a.ids, place(stats, GetParam(), {32, 32, 32}, 10).ids);
  // Fields, shapes made ahead and the field update on another thread: the same with one thread.
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(a.ids, place(stats, GetParam(), {32, 32, 32}, 9).ids);
}

// The torus's ids tiled 2x2x2, for checking what a user tiling the volume sees.
std::vector<std::int32_t> tiled(const PlacementResult& r) {
  const Dims t{2 * r.dims.x, 2 * r.dims.y, 2 * r.dims.z};
  std::vector<std::int32_t> ids(t.count());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = r.ids[r.dims.index(r.dims.wrap(t.voxel(i)))];
  return ids;
}

// In a periodic volume particles run through the faces: tiled 2x2x2, every piece of a particle's id
// that does not touch the tiling's outer faces is the whole particle (no particle is cut where the
// copies meet), and each particle has such a piece.
TEST_P(PlaceLargestFirst, APeriodicVolumeTilesWithWholeParticles) {
  const ExemplarStats stats = discStats(kDiscs, 0.25);
  const PlacementResult r = place(stats, GetParam(), {40, 44, 48}, 1, 0.8, true);
  EXPECT_TRUE(r.periodic);
  EXPECT_EQ(r.stopReason, "area fraction reached");
  EXPECT_GE(r.volumeFraction, 0.25);
  int crossing = 0;
  std::vector<std::size_t> counted(r.particles.size() + 1, 0);
  for (const std::int32_t id : r.ids) ++counted[std::size_t(id)];
  for (const PlacedParticle& p : r.particles) {
    EXPECT_EQ(counted[std::size_t(p.id)], p.voxelCount) << "particle " << p.id << " overlaps another";
    crossing += p.origin.x < 0 || p.origin.y < 0 || p.origin.z < 0 || p.origin.x + p.box.x > r.dims.x ||
                p.origin.y + p.box.y > r.dims.y || p.origin.z + p.box.z > r.dims.z;
  }
  EXPECT_GE(crossing, 3) << "no particle crosses a face: the test sees nothing";

  const Dims t{2 * r.dims.x, 2 * r.dims.y, 2 * r.dims.z};
  const std::vector<std::int32_t> ids = tiled(r);
  std::vector<std::uint8_t> seen(ids.size(), 0);
  std::vector<int> whole(r.particles.size() + 1, 0);
  const int step[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  for (std::size_t start = 0; start < ids.size(); ++start) {
    if (ids[start] == 0 || seen[start]) continue;
    std::vector<std::size_t> piece{start};
    seen[start] = 1;
    bool touchesOuterFace = false;
    for (std::size_t q = 0; q < piece.size(); ++q) {
      const Voxel v = t.voxel(piece[q]);
      for (const auto& s : step) {
        if (!t.contains(v.x + s[0], v.y + s[1], v.z + s[2])) {
          touchesOuterFace = true;
          continue;
        }
        const std::size_t n = t.index(v.x + s[0], v.y + s[1], v.z + s[2]);
        if (ids[n] == ids[start] && !seen[n]) {
          seen[n] = 1;
          piece.push_back(n);
        }
      }
    }
    if (touchesOuterFace) continue;
    const PlacedParticle& p = r.particles[std::size_t(ids[start] - 1)];
    EXPECT_EQ(piece.size(), p.voxelCount) << "particle " << p.id << " is cut where the copies meet";
    ++whole[std::size_t(p.id)];
  }
  for (const PlacedParticle& p : r.particles) EXPECT_GE(whole[std::size_t(p.id)], 1) << "particle " << p.id;

  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(r.ids, place(stats, GetParam(), {40, 44, 48}, 1, 0.8, true).ids);
}

INSTANTIATE_TEST_SUITE_P(AllKinds, PlaceLargestFirst,
                         testing::Values(PlacerKind::Discrete, PlacerKind::Brute, PlacerKind::Edt,
                                         PlacerKind::Delaunay),
                         [](const testing::TestParamInfo<PlacerKind>& info) {
                           return placerName(info.param);
                         });

TEST(PlaceLargestFirstHistogram, FollowsThePhotosProportions) {
  const ExemplarStats stats = discStats(kDiscs, 0.3);
  const PlacementResult r = place(stats, PlacerKind::Edt, {64, 64, 64}, 3, 0.6);
  expectConsistent(r, stats);
  ASSERT_EQ(r.stopReason, "area fraction reached");
  for (int b = 0; b < 10; ++b)
    EXPECT_NEAR(r.volumeHistogram[std::size_t(b)], stats.histogram.ratios[std::size_t(b)], 0.08)
        << "bin " << b;
}

TEST(PlaceLargestFirstHistogram, PlacesLargestBinsFirst) {
  const ExemplarStats stats = discStats(kDiscs, 0.15);
  const PlacementResult r = place(stats, PlacerKind::Edt, {48, 48, 48}, 4);
  ASSERT_FALSE(r.particles.empty());
  EXPECT_EQ(r.particles.front().bin, 9);  // the one 10-pixel disc is the largest bin
}

TEST(PlaceLargestFirstOptions, NothingToPlaceForAZeroFraction) {
  const ExemplarStats stats = discStats(kDiscs, 0);
  const PlacementResult r = place(stats, PlacerKind::Discrete, {16, 16, 16});
  EXPECT_TRUE(r.particles.empty());
  EXPECT_EQ(r.volumeFraction, 0);
  EXPECT_FALSE(r.stopReason.empty());
}

// The share of the voxels within `depth` of a face that particles occupy.
double faceShellFraction(const PlacementResult& r, int depth) {
  std::size_t occupied = 0, count = 0;
  for (int z = 0; z < r.dims.z; ++z)
    for (int y = 0; y < r.dims.y; ++y)
      for (int x = 0; x < r.dims.x; ++x) {
        const int toFace = std::min({x, y, z, r.dims.x - 1 - x, r.dims.y - 1 - y, r.dims.z - 1 - z});
        if (toFace >= depth) continue;
        ++count;
        occupied += r.ids[r.dims.index(x, y, z)] != 0;
      }
  return double(occupied) / double(count);
}

// A block cut out of a placement in a larger volume (the open boundary): the photo's fraction inside
// the block, particles running through its faces as often as anywhere, ids renumbered consistently.
TEST(CropToCountedBox, ABlockOfALargerPlacementHasNoWallsToThinItsFaces) {
  const ExemplarStats stats = discStats(kDiscs, 0.25);
  const ParticleFactory factory(stats, fewShapes());
  const Dims inner{48, 48, 48}, outer{64, 64, 64};
  const auto field = makeSpaciousnessField(PlacerKind::Edt, outer, 20);
  PlacementOptions options;
  options.dims = outer;
  options.counted = Box::at({8, 8, 8}, inner);
  options.voxelsPerPixel = 0.8;
  const PlacementResult whole = placeLargestFirst(stats, factory, *field, options);
  ASSERT_EQ(whole.counted, *options.counted);
  ASSERT_EQ(whole.ids.size(), inner.count());
  const PlacementResult block = cropToCountedBox(whole);
  EXPECT_NEAR(block.volumeFraction, whole.volumeFraction, 1e-12);
  EXPECT_NEAR(block.volumeFraction, 0.25, 0.02);
  ASSERT_FALSE(block.particles.empty());
  EXPECT_LT(block.particles.size(), whole.particles.size());
  std::vector<std::size_t> voxels(block.particles.size() + 1, 0);
  for (int z = 0; z < inner.z; ++z)
    for (int y = 0; y < inner.y; ++y)
      for (int x = 0; x < inner.x; ++x) {
        const std::int32_t id = block.ids[inner.index(x, y, z)];
        ++voxels[std::size_t(id)];
        if (id == 0) continue;
        const PlacedParticle& p = block.particles[std::size_t(id - 1)];
        EXPECT_EQ(p.id, id);
        EXPECT_EQ(whole.particles[std::size_t(whole.ids[inner.index(x, y, z)] - 1)].origin,
                  (Voxel{p.origin.x + 8, p.origin.y + 8, p.origin.z + 8}));
        EXPECT_TRUE(x >= p.origin.x && y >= p.origin.y && z >= p.origin.z && x < p.origin.x + p.box.x &&
                    y < p.origin.y + p.box.y && z < p.origin.z + p.box.z);
      }
  int placed = 0;
  for (const PlacedParticle& p : block.particles) {
    EXPECT_EQ(p.voxelCount, voxels[std::size_t(p.id)]);
    placed += 1;
  }
  EXPECT_EQ(placed, std::accumulate(block.placedPerBin.begin(), block.placedPerBin.end(), 0));
  // Walls keep particle centres half a particle from every face; a block's faces cut particles as
  // any plane does.
  const double shell = faceShellFraction(block, 2);
  EXPECT_NEAR(shell / block.volumeFraction, 1, 0.25);
  const PlacementResult walled = place(stats, PlacerKind::Edt, inner);
  EXPECT_LT(faceShellFraction(walled, 2) / walled.volumeFraction, shell / block.volumeFraction - 0.1);
  PlacementResult damaged = whole;
  damaged.ids.pop_back();
  EXPECT_THROW(cropToCountedBox(damaged), std::invalid_argument);
}

TEST(PlaceLargestFirstOptions, StopsAtTheParticleLimit) {
  const ExemplarStats stats = discStats(kDiscs, 0.3);
  const ParticleFactory factory(stats, fewShapes());
  const auto field = makeSpaciousnessField(PlacerKind::Edt, {40, 40, 40}, 20);
  PlacementOptions options;
  options.dims = {40, 40, 40};
  options.maxParticles = 5;
  const PlacementResult r = placeLargestFirst(stats, factory, *field, options);
  expectConsistent(r, stats);
  EXPECT_EQ(r.particles.size(), 5u);
  EXPECT_EQ(r.stopReason, "particle limit reached");
}

TEST(PlaceLargestFirstOptions, ReportsProgressAndRejectsBadOptions) {
  const ExemplarStats stats = discStats(kDiscs, 0.1);
  const ParticleFactory factory(stats, fewShapes());
  const auto field = makeSpaciousnessField(PlacerKind::Edt, {24, 24, 24}, 12);
  PlacementOptions options;
  options.dims = {24, 24, 24};
  options.voxelsPerPixel = 0.7;
  double lastFraction = -1;
  int lastPlaced = -1;
  options.progress = [&](double fraction, int placed) {
    lastFraction = fraction;
    lastPlaced = placed;
  };
  const PlacementResult r = placeLargestFirst(stats, factory, *field, options);
  EXPECT_EQ(lastPlaced, int(r.particles.size()));
  EXPECT_DOUBLE_EQ(lastFraction, r.volumeFraction);

  PlacementOptions bad = options;
  bad.voxelsPerPixel = 0;
  EXPECT_THROW(placeLargestFirst(stats, factory, *field, bad), InputError);
  bad = options;
  bad.candidatesPerTry = 0;
  EXPECT_THROW(placeLargestFirst(stats, factory, *field, bad), InputError);
  bad = options;
  bad.progressEvery = 0;
  EXPECT_THROW(placeLargestFirst(stats, factory, *field, bad), InputError);
  bad = options;
  bad.maxParticles = -1;
  EXPECT_THROW(placeLargestFirst(stats, factory, *field, bad), InputError);
  bad = options;
  bad.sizeFactor = 0;
  EXPECT_THROW(placeLargestFirst(stats, factory, *field, bad), InputError);
  bad = options;
  bad.particleWeights.assign(stats.particles.size() + 1, 1.0);
  EXPECT_THROW(placeLargestFirst(stats, factory, *field, bad), InputError);
  bad.particleWeights.assign(stats.particles.size(), 0.0);
  EXPECT_THROW(placeLargestFirst(stats, factory, *field, bad), InputError);
  bad = options;
  bad.dims = {24, 24, 25};
  EXPECT_THROW(placeLargestFirst(stats, factory, *field, bad), std::invalid_argument);
  EXPECT_THROW(placeLargestFirst(ExemplarStats{}, factory, *field, options), InputError);
}

}  // namespace
}  // namespace solidtex
