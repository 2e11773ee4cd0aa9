#include <gtest/gtest.h>

#include "TestImages.h"
#include "synthesis/growSolid.h"

using namespace solidtex;

namespace {

// A 32^3 chen-wang seed (two corrected growth levels: its 28^3 domain holds a 5^3 window at
// spacing 2 twice over) grown to a long box: one correction pass a level keeps the margin at 16
// voxels, so bricks of 24 along x work on windows shorter than the volume.
GrowOptions smallGrowth(int brickEdge) {
  GrowOptions o;
  o.seed.size = 32;
  o.volume.dims = {100, 20, 18};
  o.volume.corrections = 1;
  o.volume.seed = 3;
  o.brickEdge = brickEdge;
  return o;
}

cv::Mat photo() { return test::randomDiscs(48, 0.3, 7); }

std::vector<Rgb> grown(const GrowOptions& o) { return growSolid(photo(), o).volume.color; }

}  // namespace

TEST(GrowSolid, IsTheSeedSolidGrownByVolumeSynthesis) {
  const GrowOptions o = smallGrowth(0);
  SynthesisOptions seedOptions = o.seed;
  seedOptions.seed = o.volume.seed;
  const SolidVolume seed = synthesizeSolid(photo(), seedOptions).volume;
  DenseVolume exemplar{seed.dims, 3, {}};
  for (const Rgb& c : seed.color) exemplar.values.insert(exemplar.values.end(), c.begin(), c.end());
  const VolumeSynthesisResult expected = synthesizeFromVolume(exemplar, o.volume);

  const GrowResult result = growSolid(photo(), o);
  ASSERT_EQ(result.volume.dims, o.volume.dims);
  ASSERT_EQ(result.volume.color.size() * 3, expected.values.values.size());
  for (std::size_t i = 0; i < result.volume.color.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c)
      ASSERT_EQ(result.volume.color[i][c], expected.values.values[3 * i + c]);
  EXPECT_EQ(result.bricks, 1u);
  EXPECT_EQ(result.finestVoxels, o.volume.dims.count());
}

// Each brick's windows reach past its faces far enough (the correction margin) to equal the whole
// volume there; 24 leaves a thinner last brick along x.
TEST(GrowSolid, BricksGiveTheBytesOfTheWholeVolumeAtAnyThreadCount) {
  const std::vector<Rgb> whole = grown(smallGrowth(0));
  GrowOptions bricked = smallGrowth(24);
  bricked.volume.threads = 1;
  const GrowResult result = growSolid(photo(), bricked);
  EXPECT_EQ(result.bricks, 5u);
  EXPECT_GT(result.finestVoxels, bricked.volume.dims.count());
  EXPECT_TRUE(result.volume.color == whole);
}

TEST(GrowSolid, ProgressGoesOverTheBricks) {
  GrowOptions o = smallGrowth(20);
  std::vector<double> shares;
  int bricksNamed = 0;
  o.progress = [&](const std::string& step, double fraction) {
    if (fraction >= 0) shares.push_back(fraction);
    bricksNamed += step.find("brick 5/5") != std::string::npos;
  };
  growSolid(photo(), o);
  ASSERT_FALSE(shares.empty());
  for (std::size_t s = 1; s < shares.size(); ++s) EXPECT_GE(shares[s], shares[s - 1]);
  EXPECT_DOUBLE_EQ(shares.back(), 1);
  EXPECT_GT(bricksNamed, 0);
}
