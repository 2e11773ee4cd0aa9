#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "particles/fitHullSmoothing.h"
#include "particles/smoothHull.h"
#include "particles/visualHull.h"
#include "particles/voxelizeHull.h"
#include "shapes.h"

namespace solidtex {
namespace {

ExemplarStats ellipseStats(int count, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<std::vector<cv::Point>> contours;
  for (int i = 0; i < count; ++i) {
    const double r = 10 + 20 * uniform01(rng);
    contours.push_back(test::ellipseContour(r, r * (0.75 + 0.25 * uniform01(rng))));
  }
  return test::statsOf(contours);
}

TEST(SmoothHull, RoundsACubeIntoAClosedSurface) {
  const std::vector<Eigen::Vector2d> square{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  const HullMesh cube = visualHull({{square, Eigen::Matrix3d::Identity()}});
  const HullMesh round = smoothHull(cube, {0.12, 40});
  EXPECT_TRUE(test::closedAndConsistent(round));
  EXPECT_GT(round.volume(), 0);
  // Scaled back to the same box, the rounded cube misses its corners and edges but keeps its faces.
  const double filled =
      double(voxelize(round, Eigen::Matrix3d::Identity(), 40, 40, 40).voxelCount()) / (40 * 40 * 40);
  EXPECT_LT(filled, 0.97);
  EXPECT_GT(filled, 0.75);
  EXPECT_EQ(smoothHull(cube, {0, 40}).vertices, cube.vertices);  // radius 0: the sharp hull
}

TEST(FitHullSmoothing, RoundPhotosGetRoundParticlesAndGravelKeepsItsEdges) {
  const ExemplarStats ellipses = test::withMasks(ellipseStats(40, 3));
  const ExemplarStats gravel = test::withMasks(test::gravelStats(40, 3));
  const SmoothingFit round =
      fitHullSmoothing(ellipses, ParticleFactory(ellipses, {.shapes = 16, .seed = 1}), 1, 1, 1);
  const SmoothingFit sharp =
      fitHullSmoothing(gravel, ParticleFactory(gravel, {.shapes = 16, .seed = 1}), 1, 1, 1);
  EXPECT_GE(round.radius, 0.08);
  EXPECT_LT(sharp.radius, round.radius);
}

TEST(FitHullSmoothing, ParsesAutoOrARadius) {
  EXPECT_FALSE(parseSmoothing("auto").has_value());
  EXPECT_DOUBLE_EQ(*parseSmoothing("0.1"), 0.1);
  EXPECT_DOUBLE_EQ(*parseSmoothing("0"), 0);
  for (const char* bad : {"", "abc", "0.6", "-0.1", "nan", "0.1x"})
    EXPECT_THROW(parseSmoothing(bad), InputError) << bad;
}

}  // namespace
}  // namespace solidtex
