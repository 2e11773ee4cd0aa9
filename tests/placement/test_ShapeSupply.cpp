#include <gtest/gtest.h>

#include <vector>

#include <opencv2/imgproc.hpp>

#include "placement/detail/ShapeSupply.h"

namespace solidtex::placement::detail {
namespace {

// A photo of two particles, an ellipse and a disc, as segmentation would report it.
ExemplarStats twoParticles() {
  ExemplarStats stats;
  stats.imageWidth = stats.imageHeight = 64;
  for (const cv::Size axes : {cv::Size(9, 5), cv::Size(6, 6)}) {
    Particle2D p;
    p.id = int(stats.particles.size()) + 1;
    cv::ellipse2Poly(cv::Point(32, 32), axes, 0, 0, 360, 5, p.contour);
    p.area = cv::contourArea(p.contour);
    p.box = cv::boundingRect(p.contour);
    p.mask = cv::Mat(p.box.size(), CV_8U, cv::Scalar(255));
    p.residual = cv::Mat::zeros(p.box.size(), CV_32FC3);
    stats.particles.push_back(p);
  }
  return stats;
}

ParticleFactory factoryOf(const ExemplarStats& stats) {
  ParticleOptions options;
  options.shapes = 4;
  return ParticleFactory(stats, options);
}

}  // namespace

// Determinism across threads rests on this: the shapes a pair gets do not depend on which were made
// ahead on another thread, kept for later or made on the spot.
TEST(ShapeSupply, APairGetsTheSameShapesWhetherMadeAheadOrNot) {
  const ExemplarStats stats = twoParticles();
  const ParticleFactory factory = factoryOf(stats);
  const ShapeKey ellipse{3, 19, 11}, disc{1, 13, 13};
  ShapeSupply direct(factory, 5, 0, 1.5), ahead(factory, 5, 0, 1.5);
  const std::vector<ReadyShape> expected{direct.take(ellipse), direct.take(ellipse), direct.take(disc)};
  ahead.makeAhead(ellipse);
  ahead.makeAhead(disc);  // the ellipse's is kept for its turn
  const std::vector<ReadyShape> got{ahead.take(ellipse), ahead.take(ellipse), ahead.take(disc)};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    ASSERT_FALSE(expected[i].fit.voxels.empty());
    EXPECT_EQ(got[i].fit.voxels, expected[i].fit.voxels) << i;
    EXPECT_EQ(got[i].size.depth, expected[i].size.depth) << i;
  }
  EXPECT_NE(expected[0].fit.voxels, expected[1].fit.voxels);  // the second shape is a new draw
}

TEST(ShapeSupply, EachPhaseHasShapesOfItsOwn) {
  const ExemplarStats stats = twoParticles();
  const ParticleFactory factory = factoryOf(stats);
  const ShapeKey ellipse{3, 19, 11};
  ShapeSupply first(factory, 5, 0, 1.0), later(factory, 5, 2, 1.0);
  int same = 0;
  for (int n = 0; n < 4; ++n) same += first.take(ellipse).fit.voxels == later.take(ellipse).fit.voxels;
  EXPECT_LT(same, 2);  // four hulls to pick from: a draw or two may agree by chance, not all
}

TEST(ShapeSupply, ShapesAreMadeAtTheSupplysScale) {
  const ExemplarStats stats = twoParticles();
  const ParticleFactory factory = factoryOf(stats);
  const ShapeKey ellipse{3, 19, 11};
  ShapeSupply full(factory, 5, 0, 1.0), half(factory, 5, 0, 0.5);
  const ReadyShape a = full.take(ellipse), b = half.take(ellipse);
  EXPECT_EQ(a.fit.dims.x, 19);
  EXPECT_NEAR(b.fit.dims.x, 10, 1);
  // Half the scale in each of three directions: about an eighth of the voxels, whatever the depth drawn.
  EXPECT_LT(double(b.fit.voxels.size()), 0.5 * double(a.fit.voxels.size()));
}

}  // namespace solidtex::placement::detail
