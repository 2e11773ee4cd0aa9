#include <algorithm>
#include <numeric>

#include <gtest/gtest.h>

#include "common/Random.h"
#include "validation/particleVolumes.h"

namespace solidtex {
namespace {

double mean(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

double shareAbove(const std::vector<double>& v, double threshold) {
  return double(std::count_if(v.begin(), v.end(), [&](double x) { return x > threshold; })) /
         double(v.size());
}

// Cubes of edge 3 (three in four) and 12 at random non-overlapping places in a periodic 256^3
// volume, and the 128^3 block at (64, 64, 64) cut out of it.
struct CutBlock {
  std::vector<double> volumes;  ///< of every cube
  Dims dims{128, 128, 128};
  std::vector<std::int32_t> ids;
};

CutBlock cutBlock() {
  const int n = 256;
  const Dims whole{n, n, n};
  std::vector<std::int32_t> ids(whole.count(), 0);
  CutBlock block;
  Rng rng(5);
  for (int tries = 0; tries < 60000; ++tries) {
    const int edge = uniform01(rng) < 0.75 ? 3 : 12;
    const int x0 = int(uniform01(rng) * n), y0 = int(uniform01(rng) * n), z0 = int(uniform01(rng) * n);
    bool free = true;
    for (int z = 0; z < edge && free; ++z)
      for (int y = 0; y < edge && free; ++y)
        for (int x = 0; x < edge && free; ++x)
          free = ids[whole.index((x0 + x) % n, (y0 + y) % n, (z0 + z) % n)] == 0;
    if (!free) continue;
    block.volumes.push_back(double(edge) * edge * edge);
    for (int z = 0; z < edge; ++z)
      for (int y = 0; y < edge; ++y)
        for (int x = 0; x < edge; ++x)
          ids[whole.index((x0 + x) % n, (y0 + y) % n, (z0 + z) % n)] = std::int32_t(block.volumes.size());
  }
  block.ids.resize(block.dims.count());
  for (int z = 0; z < 128; ++z)
    for (int y = 0; y < 128; ++y)
      for (int x = 0; x < 128; ++x)
        block.ids[block.dims.index(x, y, z)] = ids[whole.index(x + 64, y + 64, z + 64)];
  return block;
}

TEST(ParticleVolumes, WholeParticlesAreCountedAsTheyAre) {
  const Dims dims{8, 8, 8};
  std::vector<std::int32_t> ids(dims.count(), 0);
  ids[dims.index(0, 0, 0)] = 2;
  ids[dims.index(1, 0, 0)] = 2;
  ids[dims.index(4, 4, 4)] = 1;
  const std::vector<double> volumes = particleVolumes(dims, ids, false);
  EXPECT_EQ(volumes, (std::vector<double>{1, 2}));
}

TEST(ParticleVolumes, ACutBlockGivesTheWholeSolidsDistribution) {
  const CutBlock block = cutBlock();
  ASSERT_GT(block.volumes.size(), 20000u);
  const std::vector<double> estimate = particleVolumes(block.dims, block.ids, true);
  ASSERT_GT(estimate.size(), 1000u);
  // A large cube lies whole in 115^3 of the block's places, a small one in 124^3: counted without
  // the correction, the large ones' share (about 0.25) would drop by a fifth, to about 0.2.
  const double truth = shareAbove(block.volumes, 100);
  EXPECT_NEAR(shareAbove(estimate, 100), truth, 0.02);
  EXPECT_NEAR(mean(estimate), mean(block.volumes), 0.08 * mean(block.volumes));
}

}  // namespace
}  // namespace solidtex
