#include <algorithm>
#include <array>
#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "common/Error.h"
#include "particles/fitBodyForm.h"
#include "particles/rotation.h"
#include "shapes.h"

namespace solidtex {
namespace {

// A photo of random plane sections of randomly turned spheroids, semi-axes (r, r, r * axisRatio),
// each kept with the chance a plane across z meets it (its z extent over its largest): ellipses of
// the plane's block of the turned quadric, which the plane's offset only scales.
ExemplarStats spheroidSectionStats(double axisRatio, int count, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<std::vector<cv::Point>> contours;
  while (int(contours.size()) < count) {
    const double r = 14 + 10 * uniform01(rng);
    const Eigen::Matrix3d turn = randomRotation(rng);
    const Eigen::Matrix3d quadric =
        turn * Eigen::Vector3d(1, 1, 1 / (axisRatio * axisRatio)).asDiagonal() * turn.transpose() / (r * r);
    if (uniform01(rng) * r > std::sqrt(quadric.inverse()(2, 2))) continue;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> plane(quadric.topLeftCorner<2, 2>());
    const double offset = 2 * uniform01(rng) - 1, shrink = std::sqrt(1 - offset * offset);
    const double major = shrink / std::sqrt(plane.eigenvalues()[0]),
                 minor = shrink / std::sqrt(plane.eigenvalues()[1]);
    if (minor < 4) continue;  // too few pixels to have a shape
    const Eigen::Vector2d axis = plane.eigenvectors().col(0);
    contours.push_back(test::ellipseContour(major, minor, {200, 200}, std::atan2(axis.y(), axis.x())));
  }
  return test::withMasks(test::statsOf(contours));
}

// The middle of a box's sides over its longest: near 1 for discs and spheres, lower for rods.
double meanMiddleOverLongest(const ParticleFactory& factory, const ExemplarStats& stats) {
  Rng rng(5);
  double sum = 0;
  for (const Particle2D& p : stats.particles) {
    const ParticleSize size = factory.pickDepth(p.box.width, p.box.height, rng);
    std::array<int, 3> sides{size.width, size.height, size.depth};
    std::sort(sides.begin(), sides.end());
    sum += double(sides[1]) / sides[2];
  }
  return sum / double(stats.particles.size());
}

TEST(PickDepth, BodyFormMovesTheMiddleSideToTheLongestOrTheShortest) {
  const ExemplarStats stats =
      test::statsOf({test::ellipseContour(29.5, 24.5), test::ellipseContour(24.5, 34.5),
                     test::ellipseContour(29.5, 39.5), test::ellipseContour(10.5, 14.5)});
  const ParticleFactory paper(stats, {.shapes = 2});
  for (const double form : {1.0, 0.5, -1.0}) {
    const ParticleFactory formed = paper.withBodyForm(form);
    Rng a(7), b(7);
    for (int i = 0; i < 100; ++i) {
      const ParticleSize drawn = paper.pickDepth(60, 50, a), made = formed.pickDepth(60, 50, b);
      std::array<int, 3> before{drawn.width, drawn.height, drawn.depth},
          after{made.width, made.height, made.depth};
      std::sort(before.begin(), before.end());
      std::sort(after.begin(), after.end());
      EXPECT_EQ(after[0], before[0]);
      EXPECT_EQ(after[2], before[2]);
      const double target = form > 0 ? before[2] : before[0];
      EXPECT_NEAR(after[1], before[1] + std::abs(form) * (target - before[1]), 0.5) << form;
      EXPECT_EQ(made.source, drawn.source);
    }
  }
  EXPECT_THROW(paper.withBodyForm(1.5), InputError);
}

TEST(FitBodyForm, SectionsOfFlattenedBodiesGiveDiscsAndOfSpheresThePapersBoxes) {
  const ExemplarStats flat = spheroidSectionStats(0.45, 150, 1);
  const ExemplarStats round = spheroidSectionStats(1, 150, 2);
  const ParticleFactory flatHulls(flat, {.shapes = 32, .seed = 1});
  const BodyFormFit discs = fitBodyForm(flat, flatHulls, 1, 1);
  const BodyFormFit spheres = fitBodyForm(round, ParticleFactory(round, {.shapes = 32, .seed = 1}), 1, 1);
  EXPECT_GE(discs.form, 0.25);
  EXPECT_EQ(spheres.form, 0);
  // The discs' boxes have two long sides, as the spheroids do; the paper's boxes are triaxial.
  EXPECT_GT(meanMiddleOverLongest(flatHulls.withBodyForm(discs.form), flat),
            meanMiddleOverLongest(flatHulls, flat) + 0.05);
}

TEST(FitBodyForm, ParsesAutoOrAForm) {
  EXPECT_FALSE(parseBodyForm("auto").has_value());
  EXPECT_DOUBLE_EQ(*parseBodyForm("0.5"), 0.5);
  EXPECT_DOUBLE_EQ(*parseBodyForm("-1"), -1);
  for (const char* bad : {"", "1.5", "-2", "disc", "0.5x", "nan"})
    EXPECT_THROW(parseBodyForm(bad), InputError) << bad;
}

}  // namespace
}  // namespace solidtex
