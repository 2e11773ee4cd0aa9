#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "TestImages.h"
#include "common/Random.h"
#include "synthesis/detail/ExemplarPyramid.h"
#include "synthesis/detail/HaarPyramid.h"
#include "synthesis/detail/rebuildSkeletalSolid.h"

using namespace solidtex;
using namespace solidtex::synthesis::detail;

namespace {

void expectSameImage(const RgbImage& a, const RgbImage& b, float tolerance) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  for (std::size_t i = 0; i < a.data.size(); ++i) ASSERT_NEAR(a.data[i], b.data[i], tolerance) << i;
}

}  // namespace

TEST(Haar, RoundTripIsExact) {
  const RgbImage image = toRgbImage(test::randomImage(18, 12, 1));
  const HaarLevel level = haarForward(image);
  EXPECT_EQ(level.approximation.width, 9);
  EXPECT_EQ(level.approximation.height, 6);
  expectSameImage(level.approximation, halve(image), 1e-7f);
  expectSameImage(haarInverse(level.approximation, level.details), image, 1e-6f);
}

TEST(Haar, PyramidCropsToItsMultipleAndItsSkeletonIsTheHalvedExemplar) {
  const RgbImage image = toRgbImage(test::randomImage(21, 18, 2));
  const HaarPyramid p = buildHaarPyramid(image, 2);
  EXPECT_EQ(p.finest.width, 20);
  EXPECT_EQ(p.finest.height, 16);
  ASSERT_EQ(p.details.size(), 2u);
  EXPECT_EQ(p.details[0].width, 10);
  EXPECT_EQ(p.details[1].width, 5);
  expectSameImage(p.coarse, halve(halve(image)), 1e-6f);
  RgbImage back = p.coarse;
  for (int l = 1; l >= 0; --l) back = haarInverse(back, p.details[std::size_t(l)]);
  expectSameImage(back, p.finest, 1e-6f);
}

// A coarse image that copies skeleton pixels rebuilds to the exemplar's blocks under those pixels.
TEST(Haar, RebuildingCopiesTheSourcesBlocks) {
  const HaarPyramid p = buildHaarPyramid(toRgbImage(test::randomImage(24, 16, 3)), 2);
  RgbImage coarse{5, 3, std::vector<float>(5 * 3 * 3)};
  std::vector<std::int32_t> sources(15);
  Rng rng(4);
  for (int i = 0; i < 15; ++i) {
    sources[std::size_t(i)] = std::int32_t(uniformIndex(rng, std::uint64_t(p.coarse.pixelCount())));
    std::copy_n(p.coarse.data.data() + 3 * sources[std::size_t(i)], 3, coarse.data.data() + 3 * i);
  }
  const RgbImage rebuilt = rebuildFromSources(coarse, sources, p);
  ASSERT_EQ(rebuilt.width, 20);
  ASSERT_EQ(rebuilt.height, 12);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 20; ++x) {
      const int s = sources[std::size_t((y / 4) * 5 + x / 4)];
      const int fx = 4 * (s % p.coarse.width) + x % 4, fy = 4 * (s / p.coarse.width) + y % 4;
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(rebuilt.at(x, y)[c], p.finest.at(fx, fy)[c], 1e-5f);
    }
}

// Every slice of a coarse solid that copies one skeleton pixel rebuilds to that pixel's 2x2 block in
// each direction; a fine voxel holds the pixel's colour plus the three directions' details over sqrt(3).
TEST(Haar, ASolidOfOneSourceRebuildsToItsBlockInThreeOrientations) {
  const HaarPyramid p = buildHaarPyramid(toRgbImage(test::randomImage(8, 8, 5)), 1);
  const int s = 5;  // skeleton pixel (1, 1)
  WorkVolume coarse;
  coarse.n = 4;
  coarse.source.assign(coarse.count(), s);
  for (std::size_t i = 0; i < coarse.count(); ++i)
    coarse.rgb.insert(coarse.rgb.end(), p.coarse.at(1, 1), p.coarse.at(1, 1) + 3);
  const WorkVolume fine = rebuildSkeletalSolid(coarse, p);
  ASSERT_EQ(fine.n, 8);
  // Voxel (x, y, z): x-slices put exemplar x along y and exemplar y along z, y-slices (x, z), z-slices (x,
  // y).
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x)
        for (int c = 0; c < 3; ++c) {
          const float a = p.coarse.at(1, 1)[c];
          const float details = p.finest.at(2 + y % 2, 2 + z % 2)[c] + p.finest.at(2 + x % 2, 2 + z % 2)[c] +
                                p.finest.at(2 + x % 2, 2 + y % 2)[c] - 3 * a;
          const float expected = std::clamp(a + details / std::sqrt(3.0f), 0.0f, 1.0f);
          ASSERT_NEAR(fine.at(fine.index(x, y, z))[c], expected, 1e-5f);
        }
}
