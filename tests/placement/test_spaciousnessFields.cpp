#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/Error.h"
#include "placement/SpaciousnessField.h"
#include "placement/exactSpaciousness.h"
#include "scenes.h"

namespace solidtex {
namespace {

using test::Scene;

const Dims kDims{24, 28, 32};

// What each kind promises against the exact spaciousness (capped at maxRadius).
void expectConsistent(PlacerKind kind, float value, double exact, float maxRadius, const Voxel& v) {
  const double capped = std::min(exact, double(maxRadius));
  SCOPED_TRACE(testing::Message() << placerName(kind) << " at (" << v.x << "," << v.y << "," << v.z << ")");
  if (kind == PlacerKind::Discrete) {
    EXPECT_LE(value, capped + 1e-4);
    EXPECT_GE(value, capped / std::sqrt(3.0) - 1e-4);
  } else if (kind ==
             PlacerKind::Delaunay) {  // a sample of the surface, one voxel of slack, jittered vertices
    EXPECT_LE(value, capped + 1e-4);
    EXPECT_GE(value, capped - 1.02);
  } else {
    EXPECT_NEAR(value, capped, 1e-4);
  }
}

// Compares every voxel; stops at the first few failures to keep the output readable.
void expectFieldConsistent(const SpaciousnessField& field, const Scene& scene, float maxRadius) {
  const std::vector<double> exact = scene.exactField();
  for (std::size_t i = 0; i < exact.size() && !testing::Test::HasFailure(); ++i) {
    const Voxel v = scene.dims().voxel(i);
    expectConsistent(field.kind(), field.at(v), exact[i], maxRadius, v);
  }
}

class FieldTest : public testing::TestWithParam<PlacerKind> {};

TEST_P(FieldTest, EmptyVolumeHoldsTheWallDistance) {
  const auto field = makeSpaciousnessField(GetParam(), kDims, 9.5f);
  EXPECT_EQ(field->kind(), GetParam());
  EXPECT_EQ(field->dims(), kDims);
  EXPECT_FLOAT_EQ(field->maxRadius(), 9.5f);
  const auto wallDistanceAt = [&](const Voxel& v, float exact) {
    if (GetParam() == PlacerKind::Delaunay)
      expectConsistent(GetParam(), field->at(v), exact, 9.5f, v);  // a bound
    else
      EXPECT_FLOAT_EQ(field->at(v), std::min(exact, 9.5f));
  };
  wallDistanceAt({0, 5, 7}, 1);
  wallDistanceAt({3, 27, 12}, 1);
  wallDistanceAt({4, 6, 8}, 5);
  wallDistanceAt({12, 14, 16}, 12);  // capped
}

TEST_P(FieldTest, MatchesTheExactSpaciousnessAfterEachInsertion) {
  for (const float maxRadius : {4.5f, 60.0f}) {
    SCOPED_TRACE(testing::Message() << "maxRadius " << maxRadius);
    const auto field = makeSpaciousnessField(GetParam(), kDims, maxRadius);
    Scene scene(kDims);
    Rng rng(7);
    for (int particle = 0; particle < 8 && !HasFailure(); ++particle) {
      field->insert(scene.addRandomParticle(rng));
      expectFieldConsistent(*field, scene, maxRadius);
    }
  }
}

TEST_P(FieldTest, BestFitGivesDistinctFreeSpotsSmallestFirst) {
  const auto field = makeSpaciousnessField(GetParam(), kDims, 8.5f);
  Scene scene(kDims);
  Rng rng(11);
  for (int particle = 0; particle < 10; ++particle) field->insert(scene.addRandomParticle(rng));
  for (const float radius : {0.5f, 2.0f, 3.2f, 6.0f}) {
    SCOPED_TRACE(testing::Message() << "radius " << radius);
    const std::vector<Voxel> spots = field->bestFit(radius, 40, rng);
    EXPECT_FALSE(spots.empty());
    EXPECT_LE(spots.size(), 40u);
    const std::vector<double> exact = scene.exactField();
    for (std::size_t i = 0; i < spots.size(); ++i) {
      EXPECT_FALSE(scene.occupied(spots[i]));
      EXPECT_GE(exact[kDims.index(spots[i])], radius - field->slack() - 1e-6);
      EXPECT_GE(field->at(spots[i]), radius - field->slack());
      EXPECT_EQ(std::count(spots.begin(), spots.end(), spots[i]), 1);
      // The Delaunay field orders by its candidates' values, not by at() (a bound from the nearest vertex).
      if (i > 0 && GetParam() != PlacerKind::Delaunay) {
        EXPECT_LE(field->at(spots[i - 1]), field->at(spots[i]));
      }
    }
  }
  EXPECT_TRUE(field->bestFit(8.6f, 10, rng).empty());  // above the cap
}

TEST_P(FieldTest, BestFitIsDeterministicForTheSeed) {
  const auto run = [](std::uint64_t seed) {
    const auto field = makeSpaciousnessField(GetParam(), kDims, 7.5f);
    Scene scene(kDims);
    Rng sceneRng(3), rng(seed);
    std::vector<Voxel> all;
    for (int particle = 0; particle < 6; ++particle) {
      field->insert(scene.addRandomParticle(sceneRng));
      for (const Voxel& v : field->bestFit(1.5f, 16, rng)) all.push_back(v);
    }
    return all;
  };
  const std::vector<Voxel> first = run(5);
  EXPECT_EQ(first, run(5));
  EXPECT_NE(first, run(6));
}

TEST_P(FieldTest, RejectsVoxelsOutsideTheVolume) {
  const auto field = makeSpaciousnessField(GetParam(), kDims, 5);
  EXPECT_THROW(field->at({-1, 0, 0}), std::out_of_range);
  EXPECT_THROW(field->insert({{1, 1, 1}, {24, 0, 0}}), std::out_of_range);
}

// On a torus no wall bounds a value and distances wrap around: a particle across a face is as near as
// one beside it.
TEST_P(FieldTest, MatchesTheExactSpaciousnessAroundATorus) {
  for (const float maxRadius : {4.5f, 60.0f}) {
    SCOPED_TRACE(testing::Message() << "maxRadius " << maxRadius);
    const auto field = makeSpaciousnessField(GetParam(), kDims, maxRadius, true);
    EXPECT_TRUE(field->periodic());
    Scene scene(kDims, true);
    EXPECT_NEAR(field->at({0, 0, 0}), maxRadius, 1e-4);  // no walls: the cap everywhere
    Rng rng(7);
    int crossing = 0;
    for (int particle = 0; particle < 10 && !HasFailure(); ++particle) {
      const std::vector<Voxel> voxels = scene.addRandomParticle(rng);
      crossing += std::any_of(voxels.begin(), voxels.end(),
                              [](const Voxel& v) { return !kDims.contains(v.x, v.y, v.z); });
      field->insert(voxels);
      expectFieldConsistent(*field, scene, maxRadius);
    }
    EXPECT_GE(crossing, 2);  // the scene tests the faces
    const std::vector<double> exact = scene.exactField();
    for (const float radius : {1.5f, 3.0f})
      for (const Voxel& spot : field->bestFit(radius, 40, rng)) {
        EXPECT_FALSE(scene.occupied(spot));
        EXPECT_GE(exact[kDims.index(spot)], radius - field->slack() - 1e-6);
      }
    // Delaunay ranks its circumcentres: each must hold its value (less the slack) around the torus.
    for (const auto& [spot, value] : field->candidates())
      EXPECT_GE(exact[kDims.index(spot)], std::min(double(value), double(maxRadius)) - field->slack() - 1e-4);
  }
}

INSTANTIATE_TEST_SUITE_P(AllKinds, FieldTest, testing::ValuesIn(placerKinds()),
                         [](const testing::TestParamInfo<PlacerKind>& info) {
                           return placerName(info.param);
                         });

// Where several voxels share the smallest value at least the radius, best fit must start there.
TEST(BucketFields, BestFitStartsAtTheSmallestSufficientValue) {
  for (const PlacerKind kind : {PlacerKind::Discrete, PlacerKind::Brute, PlacerKind::Edt}) {
    SCOPED_TRACE(placerName(kind));
    const auto field = makeSpaciousnessField(kind, kDims, 8.5f);
    Scene scene(kDims);
    Rng rng(19);
    for (int particle = 0; particle < 10; ++particle) field->insert(scene.addRandomParticle(rng));
    for (const float radius : {1.0f, 2.5f, 4.1f}) {
      float smallest = 1e9f;
      for (std::size_t i = 0; i < kDims.count(); ++i) {
        const float value = field->at(kDims.voxel(i));
        if (value >= radius) smallest = std::min(smallest, value);
      }
      const std::vector<Voxel> spots = field->bestFit(radius, 1, rng);
      ASSERT_EQ(spots.size(), 1u);
      EXPECT_FLOAT_EQ(field->at(spots[0]), smallest);
    }
  }
}

// The best candidate circumsphere is the largest empty ball up to the rounding of its centre (below)
// and the sampling of the surface (above).
TEST(DelaunayField, LargestCandidateIsTheLargestEmptyBallWithinOneVoxel) {
  const auto field = makeSpaciousnessField(PlacerKind::Delaunay, kDims, 100);
  Scene scene(kDims);
  Rng sceneRng(23), rng(1);
  for (int particle = 0; particle < 10; ++particle) {
    field->insert(scene.addRandomParticle(sceneRng));
    const std::vector<double> exact = scene.exactField();
    const double largest = *std::max_element(exact.begin(), exact.end());
    double lo = 0, hi = 100;  // largest candidate value: the last radius that still gets a spot
    while (hi - lo > 1e-3) {
      const double mid = (lo + hi) / 2;
      (field->bestFit(float(mid), 1, rng).empty() ? hi : lo) = mid;
    }
    EXPECT_LE(lo, largest + field->slack() + 1e-3) << "after particle " << particle;
    EXPECT_GE(lo, largest - 1) << "after particle " << particle;
  }
}

// The k-d tree reference equals the brute-force distance at every voxel, capped, with walls and
// around a torus.
TEST(ExactSpaciousness, MatchesBruteForceDistances) {
  for (const bool periodic : {false, true}) {
    SCOPED_TRACE(periodic ? "periodic" : "walls");
    Scene scene(kDims, periodic);
    Rng rng(29);
    std::vector<std::int32_t> ids(kDims.count(), 0);
    for (int particle = 1; particle <= 9; ++particle)
      for (const Voxel& v : scene.addRandomParticle(rng)) ids[kDims.index(kDims.wrap(v))] = particle;
    const std::vector<double> exact = scene.exactField();
    for (const float cap : {3.5f, 100.0f}) {
      const std::vector<float> field = exactSpaciousness(kDims, ids, cap, periodic);
      for (std::size_t i = 0; i < exact.size(); ++i)
        ASSERT_NEAR(field[i], std::min(exact[i], double(cap)), 1e-5) << i;
    }
  }
  EXPECT_FLOAT_EQ(
      exactSpaciousness(kDims, std::vector<std::int32_t>(kDims.count(), 0), 100)[kDims.index(0, 5, 7)], 1);
}

TEST(SpaciousnessField, ParsesPlacerNames) {
  for (const PlacerKind kind : placerKinds()) EXPECT_EQ(parsePlacerKind(placerName(kind)), kind);
  EXPECT_EQ(placerNames(), "discrete, brute, edt or delaunay");
  EXPECT_THROW(parsePlacerKind("voronoi"), InputError);
}

TEST(SpaciousnessField, RejectsAbsurdArguments) {
  EXPECT_THROW(makeSpaciousnessField(PlacerKind::Edt, {0, 4, 4}, 3), InputError);
  EXPECT_THROW(makeSpaciousnessField(PlacerKind::Discrete, {4, 4, 4}, 0), InputError);
  EXPECT_THROW(makeSpaciousnessField(PlacerKind::Delaunay, {4, 4, 4}, std::nanf("")), InputError);
  EXPECT_THROW(makeSpaciousnessField(PlacerKind::Brute, {2048, 2048, 2048}, 3), InputError);
}

}  // namespace
}  // namespace solidtex
