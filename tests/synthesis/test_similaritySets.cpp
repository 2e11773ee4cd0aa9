#include <gtest/gtest.h>

#include "TestImages.h"
#include "synthesis/detail/ExemplarNeighborhoods.h"
#include "synthesis/detail/ExemplarPyramid.h"
#include "synthesis/detail/KdTree.h"
#include "synthesis/detail/SimilaritySets.h"

using namespace solidtex;
using namespace solidtex::synthesis::detail;

namespace {

float reducedDistance(const ExemplarNeighborhoods& n, int a, int b) {
  float s = 0;
  for (int c = 0; c < n.reducedDims(); ++c)
    s += (n.reducedAt(a)[c] - n.reducedAt(b)[c]) * (n.reducedAt(a)[c] - n.reducedAt(b)[c]);
  return s;
}

void expectSameSets(const ExemplarNeighborhoods& n, const SimilaritySets& a, const SimilaritySets& b) {
  ASSERT_EQ(a.k, b.k);
  ASSERT_EQ(a.count(), b.count());
  int differentIds = 0;
  for (int m = 0; m < a.count(); ++m) {
    EXPECT_EQ(a.of(m)[0], m);
    EXPECT_EQ(b.of(m)[0], m);
    for (int q = 0; q < a.k; ++q) {
      // Same distances in the same order; ids may differ only between exact ties.
      EXPECT_NEAR(reducedDistance(n, m, a.of(m)[q]), reducedDistance(n, m, b.of(m)[q]), 1e-5f)
          << "m=" << m << " q=" << q;
      differentIds += a.of(m)[q] != b.of(m)[q];
    }
  }
  EXPECT_LE(differentIds, a.count() * a.k / 100);
}

}  // namespace

TEST(SimilaritySets, MatchBruteForceNearestNeighbours) {
  const RgbImage image = toRgbImage(test::smoothImage(40, 36));
  const ExemplarNeighborhoods n = buildExemplarNeighborhoods(image, NeighborhoodShape{4}, 8);
  ASSERT_EQ(n.count(), 37 * 33);
  expectSameSets(n, buildSimilaritySets(n, 5), bruteForceSimilaritySets(n, 5));
}

TEST(SimilaritySets, MatchBruteForceWithMinimumSeparation) {
  const RgbImage image = toRgbImage(test::randomImage(30, 30, 5));
  const ExemplarNeighborhoods n = buildExemplarNeighborhoods(image, NeighborhoodShape{6}, 10);
  const SimilaritySets sets = buildSimilaritySets(n, 5, 2);
  expectSameSets(n, sets, bruteForceSimilaritySets(n, 5, 2));
  for (int m = 0; m < sets.count(); ++m)
    for (int q = 1; q < sets.k; ++q) {
      const int o = sets.of(m)[q];
      EXPECT_TRUE(std::abs(n.centreX(o) - n.centreX(m)) > 2 || std::abs(n.centreY(o) - n.centreY(m)) > 2);
    }
}

TEST(SimilaritySets, SetsAreSortedByDistance) {
  const RgbImage image = toRgbImage(test::randomImage(24, 24, 9));
  const ExemplarNeighborhoods n = buildExemplarNeighborhoods(image, NeighborhoodShape{4}, 6);
  const SimilaritySets sets = buildSimilaritySets(n, 6);
  for (int m = 0; m < sets.count(); ++m)
    for (int q = 2; q < sets.k; ++q)
      EXPECT_LE(reducedDistance(n, m, sets.of(m)[q - 1]), reducedDistance(n, m, sets.of(m)[q]) + 1e-6f);
}

TEST(KdTree, NearestMatchesBruteForce) {
  const RgbImage image = toRgbImage(test::randomImage(20, 20, 11));
  const ExemplarNeighborhoods n = buildExemplarNeighborhoods(image, NeighborhoodShape{4}, 12);
  KdTree tree(n.reduced.data(), n.count(), n.reducedDims());
  std::vector<float> q(n.reducedDims());
  Rng rng(3);
  for (int t = 0; t < 50; ++t) {
    for (float& v : q) v = float(uniform01(rng) - 0.5);
    float best = 1e30f;
    for (int m = 0; m < n.count(); ++m) {
      float s = 0;
      for (int c = 0; c < n.reducedDims(); ++c) s += (q[c] - n.reducedAt(m)[c]) * (q[c] - n.reducedAt(m)[c]);
      best = std::min(best, s);
    }
    float d;
    tree.nearest(q.data(), &d);
    EXPECT_NEAR(d, best, 1e-5f);
  }
}
