#include <array>

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

// Three stages, each with its own share from 0 to 1: the seed, its analysis, the bricks.
TEST(GrowSolid, ProgressGoesOverTheStagesAndTheBricks) {
  GrowOptions o = smallGrowth(20);
  std::vector<std::pair<std::string, double>> steps;
  o.progress = [&](const std::string& step, double fraction) { steps.emplace_back(step, fraction); };
  growSolid(photo(), o);
  const std::array<std::string, 3> stages{"seed solid: ", "growing: analysing", "brick "};
  std::size_t s = 0;
  for (const std::string& stage : stages) {
    const std::size_t first = s;
    for (; s < steps.size() && steps[s].first.starts_with(stage); ++s) {
      EXPECT_GE(steps[s].second, 0) << steps[s].first;
      if (s > first) {
        EXPECT_GE(steps[s].second, steps[s - 1].second) << steps[s].first;
      }
    }
    EXPECT_GT(s, first) << "no step of " << stage;
  }
  EXPECT_EQ(s, steps.size()) << steps[std::min(s, steps.size() - 1)].first;
  EXPECT_NE(steps.back().first.find("brick 5/5"), std::string::npos) << steps.back().first;
  EXPECT_DOUBLE_EQ(steps.back().second, 1);
}
