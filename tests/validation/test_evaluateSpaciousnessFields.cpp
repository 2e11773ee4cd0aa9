#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "validation/evaluateSpaciousnessFields.h"

namespace solidtex {
namespace {

TEST(SummarizeErrors, MeansExtremesAndPercentileOfKnownErrors) {
  std::vector<double> errors;
  for (int i = 0; i < 100; ++i) errors.push_back(i % 2 == 0 ? -double(i) : double(i));  // -0, 1, -2, 3, ...
  const ErrorSummary s = summarizeErrors(errors);
  EXPECT_EQ(s.count, 100u);
  EXPECT_DOUBLE_EQ(s.meanError, 0.5);  // 50 pairs of (-2k, 2k + 1)
  EXPECT_DOUBLE_EQ(s.maxError, 99);
  EXPECT_DOUBLE_EQ(s.meanAbsError, 49.5);
  EXPECT_DOUBLE_EQ(s.p95AbsError, 95);
  EXPECT_DOUBLE_EQ(s.maxAbsError, 99);
  EXPECT_EQ(summarizeErrors({}).count, 0u);
}

// Two cubes in a 24^3 box, or around a 24^3 torus with the second cube across a face: the exact
// fields are exact, the others keep their stated bounds.
class EvaluateSpaciousnessFields : public testing::TestWithParam<bool> {};

TEST_P(EvaluateSpaciousnessFields, ExactFieldsAreExactAndTheOthersKeepTheirBounds) {
  const bool periodic = GetParam();
  const Dims dims{24, 24, 24};
  std::vector<std::int32_t> ids(dims.count(), 0);
  const int across = periodic ? 17 : 10;  // the second cube's x: 21..25, wrapping to 21..23, 0..1
  for (int z = 4; z < 9; ++z)
    for (int y = 4; y < 9; ++y)
      for (int x = 4; x < 9; ++x) {
        ids[dims.index(Voxel{x, y, z})] = 1;
        ids[dims.index(dims.wrap({x + across, y + 12, z + 8}))] = 2;
      }
  EXPECT_THROW(evaluateSpaciousnessFields(dims, {}, 12, 3), std::invalid_argument);
  const SpaciousnessEvaluation e = evaluateSpaciousnessFields(dims, ids, 12, 3, {}, periodic);
  ASSERT_EQ(e.fields.size(), 4u);
  EXPECT_GT(e.largestExactEmptyBall, 4);
  EXPECT_GT(e.circumcentres, 0u);
  for (const FieldEvaluation& field : e.fields) {
    EXPECT_EQ(field.freeVoxels.count, dims.count() - 2 * 125);
    EXPECT_EQ(field.circumcentres.count, e.circumcentres);
    ASSERT_EQ(field.bestFits.size(), 4u);
    const ErrorSummary& free = field.freeVoxels;
    switch (field.kind) {
      case PlacerKind::Edt:
      case PlacerKind::Brute:
        EXPECT_EQ(free.maxAbsError, 0) << placerName(field.kind);
        for (const BestFitCheck& check : field.bestFits) EXPECT_TRUE(check.agrees) << check.radius;
        break;
      case PlacerKind::Discrete:  // chamfer distances underestimate by at most 1 - 1/sqrt(3) of the value
        EXPECT_LE(free.maxError, 1e-4);
        EXPECT_LE(free.maxAbsError, e.largestExactEmptyBall * (1 - 1 / std::sqrt(3.0)) + 1e-4);
        break;
      case PlacerKind::Delaunay:  // candidates exceed the exact value by at most the slack, a voxel
        EXPECT_LE(field.circumcentres.maxError, 1 + 1e-4);
        EXPECT_EQ(field.errors.size(), e.circumcentres);
        EXPECT_LE(e.largestCircumsphereCandidate, e.largestExactEmptyBall + 1 + 1e-4);
        break;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(WallsAndTorus, EvaluateSpaciousnessFields, testing::Bool(),
                         [](const testing::TestParamInfo<bool>& info) {
                           return info.param ? "periodic" : "walls";
                         });

}  // namespace
}  // namespace solidtex
