#include <cmath>
#include <iostream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "SeamStatistics.h"
#include "common/Error.h"
#include "common/Random.h"
#include "synthesis/synthesizeFromVolume.h"
#include "validation/orientationAgreement.h"

using namespace solidtex;

namespace {

// A tile of random colours repeated to fill `side`^3.
DenseVolume tiledVolume(int tile, int side, std::uint64_t seed) {
  std::vector<float> one(std::size_t(tile * tile * tile) * 3);
  Rng rng(seed);
  for (float& v : one) v = float(uniform01(rng));
  DenseVolume out{{side, side, side}, 3, std::vector<float>(std::size_t(side) * side * side * 3)};
  for (int k = 0; k < side; ++k)
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i)
        std::copy_n(&one[(std::size_t((k % tile) * tile + j % tile) * tile + std::size_t(i % tile)) * 3], 3,
                    out.at(i, j, k));
  return out;
}

// Density bands along y with some noise: a layered material.
DenseVolume layeredVolume(int side, double period, std::uint64_t seed) {
  DenseVolume out{{side, side, side}, 1, std::vector<float>(std::size_t(side) * side * side)};
  Rng rng(seed);
  for (int k = 0; k < side; ++k)
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i)
        *out.at(i, j, k) = float(0.5 + 0.4 * std::sin(2 * M_PI * j / period) + 0.05 * (uniform01(rng) - 0.5));
  return out;
}

VolumeSynthesisOptions smallOptions(int side) {
  VolumeSynthesisOptions o;
  o.dims = {side, side, side};
  return o;
}

}  // namespace

TEST(SynthesizeFromVolume, RepeatedTileIsRebuiltFromCoherentCopies) {
  const int tile = 8;
  const DenseVolume exemplar = tiledVolume(tile, 36, 5);
  VolumeSynthesisOptions o = smallOptions(24);
  // Random colours have no dominant components: 16 dimensions keep too little of 375 to tell the
  // tile's 512 windows apart reliably.
  o.pcaDims = 24;
  const VolumeSynthesisResult r = synthesizeFromVolume(exemplar, o);
  ASSERT_EQ(r.values.dims, (Dims{24, 24, 24}));
  // Neighbours along each axis copy exemplar voxels one step apart, up to the tile's period, except
  // on the seams between patches copied at different shifts.
  int coherent = 0, pairs = 0;
  for (int k = 0; k + 1 < 24; ++k)
    for (int j = 0; j + 1 < 24; ++j)
      for (int i = 0; i + 1 < 24; ++i)
        for (int a = 0; a < 3; ++a) {
          const auto& s = r.source[r.values.dims.index(i, j, k)];
          const auto& n = r.source[r.values.dims.index(i + (a == 0), j + (a == 1), k + (a == 2))];
          const int step = int(std::lround(n[std::size_t(a)] - s[std::size_t(a)]));
          coherent += ((step - 1) % tile + tile) % tile == 0;
          ++pairs;
        }
  EXPECT_GT(double(coherent) / pairs, 0.9);
}

namespace {

// Per plane, the share of neighbour pairs that copy exemplar voxels exactly one step apart along
// their axis (up to the tile's period): coherent pairs. Where two patches copied at different
// shifts meet, or two unrelated faces, almost none are.
test::PlaneMeans coherenceByPlane(const VolumeSynthesisResult& r, int tile) {
  return test::planeMeans(r.values.dims, 4, [&](const Voxel& a, const Voxel& b, int axis) {
    const auto& s = r.source[r.values.dims.index(a)];
    const auto& n = r.source[r.values.dims.index(b)];
    for (std::size_t c = 0; c < 3; ++c) {
      const int step = int(std::lround(n[c] - s[c])) - (int(c) == axis);
      if ((step % tile + tile) % tile != 0) return 0.0;
    }
    return 1.0;
  });
}

}  // namespace

// Two copies side by side: across the face where they meet (the wrap plane) neighbours are as
// coherent as across any plane inside; without --periodic that face is a seam.
TEST(SynthesizeFromVolume, PeriodicVolumeHasNoSeamAtItsFaces) {
  const int tile = 8;
  const DenseVolume exemplar = tiledVolume(tile, 36, 5);
  VolumeSynthesisOptions o = smallOptions(32);
  o.pcaDims = 24;  // as RepeatedTileIsRebuiltFromCoherentCopies
  o.periodic = true;
  const test::PlaneMeans periodic = coherenceByPlane(synthesizeFromVolume(exemplar, o), tile);
  std::cout << "periodic: " << periodic << "\n";
  for (double wrap : periodic.wrap) EXPECT_TRUE(periodic.likeInterior(wrap)) << periodic;
  EXPECT_NEAR(periodic.wrapMean(), periodic.mean(), periodic.band());
  o.periodic = false;
  const test::PlaneMeans plain = coherenceByPlane(synthesizeFromVolume(exemplar, o), tile);
  std::cout << "not periodic: " << plain << "\n";
  for (double wrap : plain.wrap) EXPECT_LT(wrap, plain.mean() - 3 * plain.sd()) << plain;
}

TEST(SynthesizeFromVolume, SameVolumeAtAnyThreadCount) {
  const DenseVolume exemplar = layeredVolume(30, 7, 2);
  VolumeSynthesisOptions o = smallOptions(20);
  const FrameField slant3d = builtinFrameField("slant3d", o.dims);
  for (const bool periodic : {false, true})
    for (const FrameField* field : {static_cast<const FrameField*>(nullptr), &slant3d}) {
      o.periodic = periodic;
      o.field = field;
      o.threads = 1;
      const VolumeSynthesisResult one = synthesizeFromVolume(exemplar, o);
      o.threads = 2;
      const VolumeSynthesisResult two = synthesizeFromVolume(exemplar, o);
      EXPECT_EQ(one.values.values, two.values.values) << (field ? "slant3d" : "no field") << periodic;
      EXPECT_EQ(one.source, two.source);
    }
}

// Periodic: the regions' windows run past the faces and wrap (sides multiples of 4 for this exemplar's
// two corrected levels; the pyramid starts at 10x9x11).
// One case per (periodic, slant3d field): under the sanitizers each takes a minute or more.
class RegionOfTheWholeVolume : public ::testing::TestWithParam<std::tuple<bool, bool>> {};

TEST_P(RegionOfTheWholeVolume, EqualsTheSameBoxOfTheWholeVolume) {
  const auto [periodic, steered] = GetParam();
  const DenseVolume exemplar = tiledVolume(6, 30, 9);
  const Dims dims{40, 36, 44};
  const FrameField slant3d = builtinFrameField("slant3d", dims);
  VolumeSynthesisOptions o = smallOptions(40);
  o.dims = dims;
  o.field = steered ? &slant3d : nullptr;
  o.periodic = periodic;
  const VolumeSynthesisResult whole = synthesizeFromVolume(exemplar, o);
  // periodic: a box at the faces, whose windows run past them
  const Box box = periodic ? Box{{0, 1, 38}, {9, 8, 44}} : Box{{3, 17, 30}, {21, 36, 41}};
  o.region = box;
  const VolumeSynthesisResult part = synthesizeFromVolume(exemplar, o);
  const Dims d = box.dims();
  ASSERT_EQ(part.values.dims, d);
  int differing = 0;
  for (int k = 0; k < d.z; ++k)
    for (int j = 0; j < d.y; ++j)
      for (int i = 0; i < d.x; ++i)
        differing += part.source[d.index(i, j, k)] !=
                     whole.source[whole.values.dims.index(i + box.lo.x, j + box.lo.y, k + box.lo.z)];
  EXPECT_EQ(differing, 0);
}

INSTANTIATE_TEST_SUITE_P(PeriodicAndSteered, RegionOfTheWholeVolume,
                         ::testing::Combine(::testing::Bool(), ::testing::Bool()));

TEST(SynthesizeFromVolume, RefusesBadInput) {
  const DenseVolume exemplar = layeredVolume(20, 5, 1);
  VolumeSynthesisOptions o = smallOptions(16);
  EXPECT_THROW(synthesizeFromVolume(DenseVolume{{8, 8, 8}, 1, std::vector<float>(512)}, o), InputError);
  // Values out of range are the command line's errors (exit 2), each naming its option.
  auto expectOptionError = [&](const VolumeSynthesisOptions& options, const std::string& option) {
    try {
      synthesizeFromVolume(exemplar, options);
      ADD_FAILURE() << option << " was accepted";
    } catch (const OptionError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(option, 0), 0u) << e.what();
    }
  };
  o.levels = 9;
  expectOptionError(o, "--levels");
  for (const Box& region : {Box{{0, 0, 0}, {17, 4, 4}}, Box{{5, 5, 5}, {5, 5, 5}}}) {
    o = smallOptions(16);
    o.region = region;
    expectOptionError(o, "--region");
  }
  o = smallOptions(16);
  o.window = 4;
  expectOptionError(o, "--appearance");
  o = smallOptions(16);
  o.jitter = 5;
  expectOptionError(o, "--jitter");
  o = smallOptions(16);
  o.exclusion = -1;
  expectOptionError(o, "--exclusion");
  o = smallOptions(16);
  o.corrections = -1;
  expectOptionError(o, "--corrections");
  // a 16^3 domain corrects 1 level: periodic sides must be even
  o = smallOptions(16);
  o.dims = {16, 15, 16};
  o.periodic = true;
  try {
    synthesizeFromVolume(exemplar, o);
    FAIL() << "a periodic side of 15 was accepted";
  } catch (const OptionError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("16x14x16 or 16x16x16 would tile"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
}

// A large exemplar's analysis takes long before any voxel is made: the first progress says so, with
// its share; the synthesis's share then grows after every correction pass to 1.
TEST(SynthesizeFromVolume, ProgressGoesOverTheAnalysisThenThePasses) {
  VolumeSynthesisOptions o = smallOptions(16);
  std::vector<std::pair<std::string, double>> steps;
  o.progress = [&](const std::string& step, double fraction) { steps.emplace_back(step, fraction); };
  synthesizeFromVolume(layeredVolume(24, 5, 1), o);
  std::size_t analyses = 0;
  while (analyses < steps.size() && steps[analyses].first.starts_with("analysing the exemplar")) {
    EXPECT_DOUBLE_EQ(steps[analyses].second, double(analyses) / 2) << steps[analyses].first;
    ++analyses;
  }
  EXPECT_EQ(analyses, 2u);  // a 24^3 exemplar's 20^3 domain holds 5^3 windows at spacings 1 and 2
  ASSERT_LT(analyses, steps.size());
  EXPECT_EQ(steps[analyses].first.rfind("level 1/", 0), 0u) << steps[analyses].first;
  int passes = 0;
  for (std::size_t s = analyses; s < steps.size(); ++s) {
    if (s > analyses) {
      EXPECT_GE(steps[s].second, steps[s - 1].second) << steps[s].first;
    }
    passes += steps[s].first.find(", correction ") != std::string::npos;
  }
  EXPECT_EQ(passes, 2 * o.corrections);
  EXPECT_NE(steps.back().first.find("correction 4/4"), std::string::npos) << steps.back().first;
  EXPECT_DOUBLE_EQ(steps.back().second, 1);
}

namespace {

// How well the output's gradient follows the field's turn of the exemplar's layer normal (y).
double layerAgreement(const std::string& fieldName, const Dims& dims, bool steered = true) {
  const DenseVolume exemplar = layeredVolume(40, 8, 3);
  const FrameField field = builtinFrameField(fieldName, dims);
  VolumeSynthesisOptions o;
  o.dims = dims;
  o.field = steered ? &field : nullptr;
  const VolumeSynthesisResult r = synthesizeFromVolume(exemplar, o);
  const OrientationAgreement a = orientationAgreement(
      r.values, [&](int i, int j, int k) { return Eigen::Vector3f(field.at(i, j, k).col(1)); });
  if (steered) {
    EXPECT_GT(a.voxelsCounted, a.voxelsTotal / 4) << fieldName;
  }
  std::cout << fieldName << ": mean |cos| " << a.meanAbsCos << " over " << a.voxelsCounted << " of "
            << a.voxelsTotal << " voxels\n";
  return a.meanAbsCos;
}

}  // namespace

// Thesis 5.2: under the circle field straight layers turn into rings around the centre.
TEST(SynthesizeFromVolume, CircleFieldTurnsLayersIntoRings) {
  EXPECT_GE(layerAgreement("circle", {64, 64, 16}), 0.8);
  // Straight layers against the radial direction: mean |sin| of a uniform angle, 2 / pi = 0.64.
  EXPECT_LT(layerAgreement("circle", {64, 64, 16}, false), 0.75);
}

TEST(SynthesizeFromVolume, LayersFollowEveryBuiltInField) {
  for (const std::string name : {"oval", "slant", "zigzag", "slant3d"})
    EXPECT_GE(layerAgreement(name, {64, 64, 16}), 0.8) << name;
}
