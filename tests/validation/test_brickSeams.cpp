#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "validation/brickSeams.h"

namespace solidtex {
namespace {

// Voxels taken at random with probability p; within 4 planes of x = 32 with probability pFace.
std::vector<std::int32_t> randomIds(const Dims& dims, double p, double pFace, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::int32_t> ids(dims.count());
  for (int z = 0; z < dims.z; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x)
        ids[dims.index(x, y, z)] = u(rng) < (x >= 28 && x < 36 ? pFace : p) ? 1 : 0;
  return ids;
}

// Bricks of 32 in a 64^3 volume have one inner face per axis: 8 planes each within 4 of it.
TEST(BrickSeams, FacePlanesOfAUniformVolumeAreLikeTheRest) {
  const Dims dims{64, 64, 64};
  const BrickSeams s = brickSeams(randomIds(dims, 0.4, 0.4, 1), dims, 32, 4, 16);
  EXPECT_EQ(s.facePlanes, 24);
  EXPECT_EQ(s.otherPlanes, 3 * 64 - 24);
  EXPECT_NEAR(s.faceFraction, 0.4, 0.005);
  EXPECT_NEAR(s.otherFraction, 0.4, 0.005);
  // Bernoulli windows of 256 voxels: sqrt(0.4 * 0.6 / 256) = 0.031.
  EXPECT_NEAR(s.faceWindowSpread, 0.031, 0.004);
  EXPECT_NEAR(s.otherWindowSpread, 0.031, 0.004);
}

// A denser slab along one face: its x planes are fuller, and the y and z planes that cross it
// have windows of two kinds, so the face planes' windows spread more.
TEST(BrickSeams, ASlabAlongAFaceShows) {
  const Dims dims{64, 64, 64};
  const BrickSeams s = brickSeams(randomIds(dims, 0.4, 0.6, 2), dims, 32, 4, 16);
  EXPECT_GT(s.faceFraction, s.otherFraction + 0.04);
  EXPECT_GT(s.faceWindowSpread, 1.5 * s.otherWindowSpread);
  EXPECT_THROW(brickSeams({}, dims, 32, 4, 16), std::invalid_argument);
}

}  // namespace
}  // namespace solidtex
