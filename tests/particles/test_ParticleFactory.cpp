#include <map>
#include <numbers>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "common/Error.h"
#include "particles/ParticleFactory.h"
#include "segmentation/regionShape.h"
#include "shapes.h"

namespace solidtex {
namespace {

// The paper's Fig. 4: boxes (60,50), (60,50), (50,70), (60,80).
ExemplarStats figureFourStats() {
  return test::statsOf({test::ellipseContour(29.5, 24.5), test::ellipseContour(29.5, 24.5, {300, 100}),
                        test::ellipseContour(24.5, 34.5), test::ellipseContour(29.5, 39.5)});
}

TEST(PickDepth, DrawsThePapersCandidatesByFrequency) {
  const ExemplarStats stats = figureFourStats();
  ASSERT_EQ(stats.particles[0].box.size(), cv::Size(60, 50));
  ASSERT_EQ(stats.particles[2].box.size(), cv::Size(50, 70));
  ASSERT_EQ(stats.particles[3].box.size(), cv::Size(60, 80));
  const ParticleFactory factory(stats, {.shapes = 2});
  Rng rng(7);
  std::map<int, int> depths, sources;
  const int draws = 40000;
  for (int i = 0; i < draws; ++i) {
    const ParticleSize size = factory.pickDepth(60, 50, rng);
    EXPECT_EQ(size.width, 60);
    EXPECT_EQ(size.height, 50);
    ++depths[size.depth];
    ++sources[size.source];
  }
  ASSERT_EQ(depths.size(), 4u);
  for (const int depth : {50, 60, 70, 80}) EXPECT_NEAR(double(depths[depth]) / draws, 0.25, 0.015) << depth;
  ASSERT_EQ(sources.size(), 2u);  // the two (60,50) particles, evenly
  EXPECT_NEAR(double(sources[0]) / draws, 0.5, 0.015);
  EXPECT_EQ(sources[0] + sources[1], draws);
}

TEST(PickDepth, UnknownSizesFallBackToThePhotosSides) {
  const ExemplarStats stats = figureFourStats();
  const ParticleFactory factory(stats, {.shapes = 1});
  Rng rng(3);
  for (int i = 0; i < 200; ++i) {
    const ParticleSize size = factory.pickDepth(13, 17, rng);
    EXPECT_TRUE(size.depth == 50 || size.depth == 60 || size.depth == 70 || size.depth == 80) << size.depth;
    EXPECT_TRUE(size.source == 0 || size.source == 1) << size.source;  // nearest box (60,50): |dw|+|dh| = 80
  }
}

std::vector<HullMesh> poolWithThreads(const ExemplarStats& stats, int threads) {
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
  return ParticleFactory(stats, {.shapes = 16, .seed = 42}).hulls();
}

TEST(ParticleFactory, PoolIsTheSameAtAnyThreadCount) {
  const ExemplarStats stats = test::gravelStats(40, 11);
  const std::vector<HullMesh> one = poolWithThreads(stats, 1), two = poolWithThreads(stats, 2);
  ASSERT_EQ(one.size(), 16u);
  ASSERT_EQ(two.size(), 16u);
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].triangles, two[i].triangles) << i;
    EXPECT_EQ(one[i].vertices, two[i].vertices) << i;
    EXPECT_TRUE(test::closedAndConsistent(one[i])) << i;
    EXPECT_GT(one[i].volume(), 0.01) << i;
  }
  const std::vector<HullMesh> otherSeed = ParticleFactory(stats, {.shapes = 16, .seed = 43}).hulls();
  EXPECT_NE(one[0].vertices, otherSeed[0].vertices);
}

TEST(ParticleFactory, MakesAboutTheRequestedBoxInOnePiece) {
  const ExemplarStats stats = test::gravelStats(30, 5);
  const ParticleFactory factory(stats, {.shapes = 8});
  Rng rng(9);
  for (int i = 0; i < 40; ++i) {
    const ParticleSize size = factory.pickDepth(stats.sizePairs[i % stats.sizePairs.size()].width,
                                                stats.sizePairs[i % stats.sizePairs.size()].height, rng);
    const VoxelShape shape = factory.make(size.width, size.height, size.depth, rng);
    const int asked[3] = {size.width, size.height, size.depth},
              sides[3] = {shape.dims.x, shape.dims.y, shape.dims.z};
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(sides[a], asked[a]);
      EXPECT_GE(sides[a], std::max(1, int(0.85 * asked[a]) - 1));  // see Voxelize.EveryBoxIsTight...
    }
    EXPECT_TRUE(test::tightInBox(shape));
    EXPECT_EQ(test::firstPieceSize(shape), shape.voxelCount());
    EXPECT_EQ(stats.particles[std::size_t(size.source)].box.size(), cv::Size(size.width, size.height));
  }
}

// The middle layer of a shape across `axis`, as a region in that plane's photo's image axes (x
// across for xy and xz, y for yz; then y or z down).
RegionShape middleSection(const VoxelShape& shape, int axis) {
  const int extent[3] = {shape.dims.x, shape.dims.y, shape.dims.z};
  const int across = axis == 0 ? 1 : 0, down = axis == 2 ? 1 : 2;
  std::vector<cv::Point> pixels;
  int c[3];
  c[axis] = extent[axis] / 2;
  for (c[down] = 0; c[down] < extent[down]; ++c[down])
    for (c[across] = 0; c[across] < extent[across]; ++c[across])
      if (shape.inside[shape.dims.index(c[0], c[1], c[2])]) pixels.emplace_back(c[across], c[down]);
  return measureRegion(pixels);
}

// Three planes' photos of ellipses 40 x 20 (xy), 40 x 12 (xz) and 20 x 12 (yz): an aligned
// particle is 40 x 20 x 12 deep, never turned, and its middle sections are the photos' ellipses.
TEST(ParticleFactory, AlignedParticlesTakeEachPlanesContours) {
  const ExemplarStats xy = test::statsOf({test::ellipseContour(19.5, 9.5)});
  const ExemplarStats xz = test::statsOf({test::ellipseContour(19.5, 5.5)});
  const ExemplarStats yz = test::statsOf({test::ellipseContour(9.5, 5.5)});
  const ParticleFactory factory(xy, {.shapes = 4}, {&xz, &yz});
  ASSERT_TRUE(factory.aligned());
  EXPECT_FALSE(ParticleFactory(xy, {.shapes = 1}, {&xz, nullptr}).aligned());
  Rng rng(4);
  for (int i = 0; i < 8; ++i) {
    const ParticleSize size = factory.pickDepth(40, 20, rng);
    ASSERT_EQ(size.depth, 12);
    const VoxelShape shape = factory.make(size.width, size.height, size.depth, rng);
    EXPECT_GE(shape.dims.x, 38);
    EXPECT_GE(shape.dims.y, 18);
    EXPECT_GE(shape.dims.z, 10);
    const std::pair<int, double> planes[] = {{2, 0.5}, {1, 12.0 / 40}, {0, 12.0 / 20}};
    for (const auto& [axis, aspect] : planes) {
      const RegionShape section = middleSection(shape, axis);
      EXPECT_NEAR(section.aspect, aspect, 0.05) << axis;
      EXPECT_NEAR(std::min(section.orientation, std::numbers::pi - section.orientation), 0, 0.03) << axis;
    }
  }
}

TEST(ParticleFactory, RejectsBadOptionsAndContourlessPhotos) {
  const ExemplarStats stats = figureFourStats();
  EXPECT_THROW(ParticleFactory(stats, {.views = 0}), InputError);
  EXPECT_THROW(ParticleFactory(stats, {.shapes = 0}), InputError);
  EXPECT_THROW(ParticleFactory(stats, {.contourVertices = 2}), InputError);
  EXPECT_THROW(ParticleFactory(test::statsOf({{{0, 0}, {5, 0}, {9, 0}}}), {}), InputError);
  EXPECT_THROW(ParticleFactory(ExemplarStats{}, {}), InputError);
}

}  // namespace
}  // namespace solidtex
