#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "common/Error.h"
#include "common/Random.h"
#include "validation/patchDistances.h"
#include "validation/volumeQuality.h"

namespace solidtex {
namespace {

// A sum of six plane waves of period `period` (whole frequencies 1-3 per axis), in [0,1], evaluated at
// integer coordinates wrapped into one period after the shift: voxels with the same wrapped
// coordinates are bit-identical.
DenseVolume periodicSmooth(const Dims& dims, int channels, std::uint64_t seed, int period = 32,
                           std::array<int, 3> shift = {0, 0, 0}) {
  struct Wave {
    int f[3];
    double phase, amplitude;
  };
  Rng rng(seed);
  std::vector<std::vector<Wave>> waves(static_cast<std::size_t>(channels));
  for (auto& channel : waves)
    for (int w = 0; w < 6; ++w) {
      Wave wave{};
      for (int& f : wave.f) f = int(uniformIndex(rng, 7)) - 3;
      wave.phase = 2 * std::numbers::pi * uniform01(rng);
      wave.amplitude = 0.5 + uniform01(rng);
      channel.push_back(wave);
    }
  DenseVolume v{dims, channels, std::vector<float>(dims.count() * std::size_t(channels))};
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        const int x[3] = {(i + shift[0]) % period, (j + shift[1]) % period, (k + shift[2]) % period};
        for (int c = 0; c < channels; ++c) {
          double sum = 0, total = 0;
          for (const Wave& w : waves[std::size_t(c)]) {
            sum += w.amplitude *
                   std::sin(2 * std::numbers::pi * (w.f[0] * x[0] + w.f[1] * x[1] + w.f[2] * x[2]) / period +
                            w.phase);
            total += w.amplitude;
          }
          v.at(i, j, k)[c] = float(0.5 + 0.5 * sum / total);
        }
      }
  return v;
}

// Independent uniform values in [0,1].
DenseVolume noise(const Dims& dims, int channels, std::uint64_t seed) {
  DenseVolume v{dims, channels, std::vector<float>(dims.count() * std::size_t(channels))};
  Rng rng(seed);
  for (float& x : v.values) x = float(uniform01(rng));
  return v;
}

// Two-phase material: grains where a smooth field is high, each phase its own colour, plus a little
// grain noise.
DenseVolume grains(const Dims& dims, int channels, std::uint64_t seed) {
  const DenseVolume field = periodicSmooth(dims, 1, seed, 16);
  DenseVolume v{dims, channels, std::vector<float>(dims.count() * std::size_t(channels))};
  Rng rng(deriveSeed(seed, 1));
  for (std::size_t i = 0; i < dims.count(); ++i)
    for (int c = 0; c < channels; ++c)
      v.values[i * std::size_t(channels) + std::size_t(c)] =
          (field.values[i] > 0.55f ? 0.8f - 0.2f * float(c) : 0.2f + 0.1f * float(c)) +
          0.05f * float(uniform01(rng));
  return v;
}

// Every side^3 patch of the volume as a column, in the component order of the measure.
Eigen::MatrixXf allPatches(const DenseVolume& v, int side) {
  const int nx = v.dims.x - side + 1, ny = v.dims.y - side + 1, nz = v.dims.z - side + 1,
            row = side * v.channels;
  Eigen::MatrixXf m(side * side * side * v.channels, Eigen::Index(nx) * ny * nz);
  Eigen::Index col = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i, ++col) {
        float* out = m.col(col).data();
        for (int dz = 0; dz < side; ++dz)
          for (int dy = 0; dy < side; ++dy, out += row) std::copy_n(v.at(i, j + dy, k + dz), row, out);
      }
  return m;
}

TEST(VolumeQuality, AVolumeAgainstItselfScoresZeroAndItsShuffledCopyDoesNot) {
  const DenseVolume v = grains({24, 24, 24}, 1, 3);
  const VolumeQuality q = measureVolumeQuality(v, v);
  EXPECT_LE(q.coherence, 1e-6);
  EXPECT_LE(q.completeness, 1e-6);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_LE(q.sliceCoherence[std::size_t(axis)], 1e-6);
    EXPECT_LE(q.sliceCompleteness[std::size_t(axis)], 1e-6);
    // The phases differ by 0.5 or more: a shuffled patch mixes them.
    EXPECT_GT(q.shuffledSliceCoherence[std::size_t(axis)], 0.1);
  }
  EXPECT_GT(q.shuffledCoherence, 0.15);
  EXPECT_GT(q.shuffledCompleteness, 0.15);
  EXPECT_LE(q.coherenceRatio(), 1e-5);
  ASSERT_EQ(q.valueWasserstein.size(), 1u);
  EXPECT_EQ(q.valueWasserstein[0], 0.0);  // shuffling keeps the values
  EXPECT_GT(q.exactShare, 0.99);          // an exact copy bounds every search at once
}

TEST(VolumeQuality, APeriodicShiftIsCoherentAndNoiseIsNot) {
  const Dims dims{32, 32, 32};
  const DenseVolume output = periodicSmooth(dims, 1, 7);
  // The same periodic field, shifted and 8 voxels larger: it holds a bit-identical copy of every output
  // patch (5^3 patches need 4 more voxels beyond one period).
  const DenseVolume exemplar = periodicSmooth({40, 40, 40}, 1, 7, 32, {7, 19, 26});
  const VolumeQuality shifted = measureVolumeQuality(output, exemplar);
  EXPECT_LE(shifted.coherence, 1e-6);
  EXPECT_LE(shifted.coherenceRatio(), 1e-4);
  // Exemplar patches that wrap in the output's frame have near copies only.
  EXPECT_LT(shifted.completeness, 0.1 * shifted.shuffledCompleteness);

  // Independent noise has no structure at all: shuffling it changes nothing, so its figures are the
  // shuffled level up to sampling and search error. Over 8 seeds the ratios stayed within 0.5 %
  // (coherence), 1.1 % (slices) and 3.4 % (completeness: its queries, exemplar patches, are few
  // distinct smooth shapes whose nearest noise patch depends on the draw).
  const VolumeQuality unstructured = measureVolumeQuality(noise(dims, 1, 8), exemplar);
  EXPECT_NEAR(unstructured.coherenceRatio(), 1.0, 0.02);
  EXPECT_NEAR(unstructured.sliceCoherenceRatio(), 1.0, 0.03);
  EXPECT_NEAR(unstructured.completenessRatio(), 1.0, 0.06);
  // Uniform values against a sinusoid's arcsine-like distribution: clearly apart.
  EXPECT_GT(unstructured.valueWasserstein[0], 0.05);
}

TEST(VolumeQuality, TheSearchMatchesBruteForce) {
  // 20^3 volumes hold 16^3 = 4096 patches: with 4096 samples every patch is a query, so the measure is
  // the mean over all patches that brute force computes.
  const Dims dims{20, 20, 20};
  const DenseVolume exemplar = grains(dims, 3, 11);
  const Eigen::MatrixXf exemplarPatches = allPatches(exemplar, 5);
  // Measured: textured 0.2 % and noise 0.5 % above brute force (noise patches lie mostly outside the
  // search components, so their searches stop on the budget); at 64^3 up to 1 % and 4 %.
  constexpr double tolerance = 0.02;
  for (const DenseVolume& output : {grains(dims, 3, 12), noise(dims, 3, 13)}) {
    const VolumeQuality q = measureVolumeQuality(output, exemplar);
    const Eigen::MatrixXf outputPatches = allPatches(output, 5);
    const double coherence = meanNearestPatchDistance(outputPatches, exemplarPatches),
                 completeness = meanNearestPatchDistance(exemplarPatches, outputPatches);
    // Every distance is to a real patch: never below the exact nearest.
    EXPECT_GE(q.coherence, coherence - 1e-6);
    EXPECT_GE(q.completeness, completeness - 1e-6);
    EXPECT_LE(q.coherence, coherence * (1 + tolerance));
    EXPECT_LE(q.completeness, completeness * (1 + tolerance));
  }
}

TEST(VolumeQuality, TheValueDistanceIsAConstantOffset) {
  const DenseVolume exemplar = grains({16, 16, 16}, 3, 5);
  DenseVolume output = exemplar;
  for (float& x : output.values) x += 0.125f;
  const VolumeQuality q = measureVolumeQuality(output, exemplar);
  ASSERT_EQ(q.valueWasserstein.size(), 3u);
  for (double w : q.valueWasserstein) EXPECT_NEAR(w, 0.125, 1e-6);
}

TEST(VolumeQuality, SameFiguresAtAnyThreadCount) {
  // Both hold more than 4096 patches, so that their search trees are built in parallel too.
  const DenseVolume exemplar = grains({24, 24, 24}, 3, 21), output = grains({28, 24, 20}, 3, 22);
  auto measure = [&](int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    return measureVolumeQuality(output, exemplar, {.samples = 1024});
  };
  const VolumeQuality a = measure(1), b = measure(2);
  EXPECT_EQ(a.coherence, b.coherence);
  EXPECT_EQ(a.completeness, b.completeness);
  EXPECT_EQ(a.shuffledCoherence, b.shuffledCoherence);
  EXPECT_EQ(a.shuffledCompleteness, b.shuffledCompleteness);
  EXPECT_EQ(a.sliceCoherence, b.sliceCoherence);
  EXPECT_EQ(a.sliceCompleteness, b.sliceCompleteness);
  EXPECT_EQ(a.shuffledSliceCoherence, b.shuffledSliceCoherence);
  EXPECT_EQ(a.shuffledSliceCompleteness, b.shuffledSliceCompleteness);
  EXPECT_EQ(a.valueWasserstein, b.valueWasserstein);
  EXPECT_EQ(a.exactShare, b.exactShare);
  EXPECT_EQ(a.shuffledExactShare, b.shuffledExactShare);
}

TEST(VolumeQuality, RejectsInconsistentInput) {
  const DenseVolume grey = grains({12, 12, 12}, 1, 1), colour = grains({12, 12, 12}, 3, 1);
  EXPECT_THROW(measureVolumeQuality(grey, colour), InputError);
  EXPECT_THROW(measureVolumeQuality(grains({4, 12, 12}, 1, 1), grey), InputError);  // 5^3 does not fit
  EXPECT_THROW(measureVolumeQuality(grey, grey, {.patch = 4}), InputError);
  DenseVolume truncated = grey;
  truncated.values.pop_back();
  EXPECT_THROW(measureVolumeQuality(truncated, grey), InputError);
}

}  // namespace
}  // namespace solidtex
