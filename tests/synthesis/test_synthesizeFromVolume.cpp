#include <cmath>
#include <iostream>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

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

TEST(SynthesizeFromVolume, SameVolumeAtAnyThreadCount) {
  const DenseVolume exemplar = layeredVolume(30, 7, 2);
  VolumeSynthesisOptions o = smallOptions(20);
  const FrameField slant3d = builtinFrameField("slant3d", o.dims);
  for (const FrameField* field : {static_cast<const FrameField*>(nullptr), &slant3d}) {
    o.field = field;
    o.threads = 1;
    const VolumeSynthesisResult one = synthesizeFromVolume(exemplar, o);
    o.threads = 2;
    const VolumeSynthesisResult two = synthesizeFromVolume(exemplar, o);
    EXPECT_EQ(one.values.values, two.values.values) << (field ? "slant3d" : "no field");
    EXPECT_EQ(one.source, two.source);
  }
}

TEST(SynthesizeFromVolume, RegionEqualsTheSameBoxOfTheWholeVolume) {
  const DenseVolume exemplar = tiledVolume(6, 30, 9);
  const Dims dims{40, 36, 44};
  const FrameField slant3d = builtinFrameField("slant3d", dims);
  for (const FrameField* field : {static_cast<const FrameField*>(nullptr), &slant3d}) {
    VolumeSynthesisOptions o = smallOptions(40);
    o.dims = dims;
    o.field = field;
    const VolumeSynthesisResult whole = synthesizeFromVolume(exemplar, o);
    o.region = VoxelBox{{3, 17, 30}, {21, 36, 41}};
    const VolumeSynthesisResult part = synthesizeFromVolume(exemplar, o);
    ASSERT_EQ(part.values.dims, (Dims{18, 19, 11}));
    int differing = 0;
    for (int k = 0; k < 11; ++k)
      for (int j = 0; j < 19; ++j)
        for (int i = 0; i < 18; ++i)
          differing += part.source[part.values.dims.index(i, j, k)] !=
                       whole.source[whole.values.dims.index(i + 3, j + 17, k + 30)];
    EXPECT_EQ(differing, 0) << (field ? "slant3d" : "isometric");
  }
}

TEST(SynthesizeFromVolume, RefusesBadInput) {
  const DenseVolume exemplar = layeredVolume(20, 5, 1);
  VolumeSynthesisOptions o = smallOptions(16);
  EXPECT_THROW(synthesizeFromVolume(DenseVolume{{8, 8, 8}, 1, std::vector<float>(512)}, o), InputError);
  o.levels = 9;
  EXPECT_THROW(synthesizeFromVolume(exemplar, o), InputError);
  o = smallOptions(16);
  o.region = VoxelBox{{0, 0, 0}, {17, 4, 4}};
  EXPECT_THROW(synthesizeFromVolume(exemplar, o), InputError);
  o = smallOptions(16);
  o.window = 4;
  EXPECT_THROW(synthesizeFromVolume(exemplar, o), InputError);
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
