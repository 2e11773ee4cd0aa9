#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <set>
#include <tuple>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "common/Error.h"
#include "common/Random.h"
#include "segmentation/analyzeExemplar.h"
#include "validation/particleTruth.h"

namespace solidtex {
namespace {

// Two classes 10:1 in median volume, the widest size mix the truth family covers.
ParticleTruthOptions smallTruth(TruthShape shape = TruthShape::Ellipsoid) {
  ParticleTruthOptions options;
  options.dims = {160, 160, 64};
  options.classes = {{4, 0.2, 0.75, {0.92f, 0.55f, 0.16f}},
                     {4 * std::cbrt(10.0), 0.15, 0.25, {0.25f, 0.48f, 0.88f}}};
  options.shape = shape;
  options.seed = 3;
  return options;
}

// One class of mid-sized particles: large enough for their voxels to show their shape.
ParticleTruthOptions shapeTruth(TruthShape shape, double elongation, double flatten) {
  ParticleTruthOptions options = smallTruth(shape);
  options.classes = {{7, 0.1, 1, {0.92f, 0.55f, 0.16f}}};
  options.elongation = elongation;
  options.flatten = flatten;
  return options;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Each particle's voxel centres, unwrapped across the periodic edges next to its first voxel.
std::vector<std::vector<Eigen::Vector3d>> particleVoxels(const ParticleTruth& t) {
  const Dims& d = t.volume.dims;
  const Eigen::Vector3d size(d.x, d.y, d.z);
  std::vector<std::vector<Eigen::Vector3d>> voxels(t.volumes.size());
  for (std::size_t v = 0; v < d.count(); ++v) {
    const std::int32_t id = t.volume.particleId[v];
    if (id == 0) continue;
    const Voxel c = d.voxel(v);
    Eigen::Vector3d p(c.x, c.y, c.z);
    std::vector<Eigen::Vector3d>& mine = voxels[std::size_t(id - 1)];
    if (!mine.empty()) p -= (size.array() * ((p - mine.front()).array() / size.array()).round()).matrix();
    mine.push_back(p);
  }
  return voxels;
}

struct Moments {
  Eigen::Vector3d mean;
  Eigen::Matrix3d axes;       // columns: principal directions, smallest spread first
  Eigen::Vector3d variances;  // ascending
};

Moments momentsOf(const std::vector<Eigen::Vector3d>& voxels) {
  Moments m;
  m.mean.setZero();
  for (const Eigen::Vector3d& p : voxels) m.mean += p / double(voxels.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : voxels)
    covariance += (p - m.mean) * (p - m.mean).transpose() / double(voxels.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  m.axes = solver.eigenvectors();
  m.variances = solver.eigenvalues();
  return m;
}

// The share of the box along the particle's principal axes (voxels one unit wide) it fills.
double orientedBoxFill(const std::vector<Eigen::Vector3d>& voxels) {
  const Moments m = momentsOf(voxels);
  Eigen::Vector3d low = Eigen::Vector3d::Constant(1e9), high = -low;
  for (const Eigen::Vector3d& p : voxels) {
    const Eigen::Vector3d q = m.axes.transpose() * (p - m.mean);
    low = low.cwiseMin(q);
    high = high.cwiseMax(q);
  }
  return double(voxels.size()) / (high - low + Eigen::Vector3d::Ones()).prod();
}

// Of points a quarter, half and three quarters along random chords between a particle's voxels,
// the share whose nearest voxel is the particle's: near 1 for a convex particle, where only the
// rounding at its surface misses; a dent or a waist loses whole chords.
double chordShareInside(const std::vector<Eigen::Vector3d>& voxels, Rng& rng) {
  std::set<std::tuple<int, int, int>> members;
  for (const Eigen::Vector3d& p : voxels) members.insert({int(p.x()), int(p.y()), int(p.z())});
  int inside = 0, total = 0;
  for (int pair = 0; pair < 300; ++pair) {
    const Eigen::Vector3d& a = voxels[uniformIndex(rng, voxels.size())];
    const Eigen::Vector3d& b = voxels[uniformIndex(rng, voxels.size())];
    for (double t : {0.25, 0.5, 0.75}) {
      const Eigen::Vector3d p = (a + t * (b - a)).array().round();
      inside += members.contains({int(p.x()), int(p.y()), int(p.z())});
      ++total;
    }
  }
  return double(inside) / total;
}

// Made once per test run: the tests only vary these options.
const ParticleTruth& truthOf(const ParticleTruthOptions& options) {
  static std::map<std::tuple<TruthShape, double, double, std::size_t, std::vector<double>>,
                  std::unique_ptr<ParticleTruth>>
      made;
  std::unique_ptr<ParticleTruth>& truth =
      made[{options.shape, options.elongation, options.flatten, options.classes.size(), options.anisotropy}];
  if (!truth) truth = std::make_unique<ParticleTruth>(makeParticleTruth(options));
  return *truth;
}

class ParticleTruthShapes : public testing::TestWithParam<TruthShape> {};

TEST_P(ParticleTruthShapes, FillsTheAskedFractionWithParticlesThatNeverTouch) {
  const ParticleTruth& t = truthOf(smallTruth(GetParam()));
  const Dims& d = t.volume.dims;
  EXPECT_NEAR(t.volumeFraction, 0.2, 0.02);  // a few of the last, small ones may find no room
  std::vector<double> counted(t.volumes.size(), 0);
  for (int k = 0; k < d.z; ++k)
    for (int j = 0; j < d.y; ++j)
      for (int i = 0; i < d.x; ++i) {
        const std::int32_t id = t.volume.particleId[d.index(i, j, k)];
        if (id == 0) continue;
        ++counted[std::size_t(id - 1)];
        // Periodic 26-neighbourhood: another particle there would merge with this one in a section.
        for (int dk = -1; dk <= 1; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
              const std::int32_t other =
                  t.volume
                      .particleId[d.index((i + di + d.x) % d.x, (j + dj + d.y) % d.y, (k + dk + d.z) % d.z)];
              ASSERT_TRUE(other == 0 || other == id) << "particles " << id << " and " << other << " touch";
            }
      }
  EXPECT_EQ(counted, t.volumes);
}

// Every shape is scaled to the volume of its equal-volume sphere, so the medians of the measured
// volumes are those of the size law (radius 4 and 10^(1/3) x 4: 10:1 in volume).
TEST_P(ParticleTruthShapes, ClassesHaveTheirSizesAndShares) {
  const ParticleTruthOptions options = smallTruth(GetParam());
  const ParticleTruth& t = truthOf(options);
  std::vector<double> small, large;
  for (std::size_t p = 0; p < t.volumes.size(); ++p)
    (t.classOf[p] == 0 ? small : large).push_back(t.volumes[p]);
  const auto sphere = [](double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; };
  EXPECT_NEAR(median(small) / sphere(options.classes[0].meanRadius), 1, 0.15);
  EXPECT_NEAR(median(large) / sphere(options.classes[1].meanRadius), 1, 0.15);
  EXPECT_NEAR(median(large) / median(small), 10, 1.5);
  EXPECT_NEAR(double(large.size()) / double(t.volumes.size()), 0.25, 0.05);
}

// The photo is the middle section: particle pixels in their class colour, background elsewhere, so
// segmenting it finds the section's particles and its area fraction.
TEST_P(ParticleTruthShapes, PhotoIsTheMiddleSectionInClassColors) {
  const ParticleTruthOptions options = smallTruth(GetParam());
  const ParticleTruth& t = truthOf(options);
  const Dims& d = t.volume.dims;
  std::size_t filled = 0;
  for (int j = 0; j < d.y; ++j)
    for (int i = 0; i < d.x; ++i) {
      const std::int32_t id = t.volume.particleId[d.index(i, j, d.z / 2)];
      filled += id > 0;
      const cv::Vec3f expected =
          id > 0 ? options.classes[std::size_t(t.classOf[std::size_t(id - 1)])].srgb : options.backgroundSrgb;
      // Shading within 6 % and noise of 0.02: five standard deviations, clamped to [0, 1].
      ASSERT_LT(cv::norm(t.photo.at<cv::Vec3f>(j, i) - expected, cv::NORM_INF), 0.06 + 5 * options.noise);
    }
  const ExemplarStats stats = analyzeExemplar(t.photo, "truth", SegmentationOptions{});
  EXPECT_NEAR(stats.areaFraction, double(filled) / (d.x * d.y), 0.01);
}

INSTANTIATE_TEST_SUITE_P(Shapes, ParticleTruthShapes,
                         testing::Values(TruthShape::Ellipsoid, TruthShape::Superellipsoid,
                                         TruthShape::Polytope),
                         [](const testing::TestParamInfo<TruthShape>& info) {
                           return truthShapeName(info.param);
                         });

// Spheres flattened to 0.45: the square root of the smallest over the largest second moment of
// each particle's voxels is its axis ratio.
TEST(ParticleTruth, FlattenSetsTheAxisRatio) {
  const ParticleTruth& t = truthOf(shapeTruth(TruthShape::Ellipsoid, 1, 0.45));
  std::vector<double> ratios;
  for (const auto& voxels : particleVoxels(t)) {
    const Eigen::Vector3d v = momentsOf(voxels).variances;
    ratios.push_back(std::sqrt(v[0] / v[2]));
  }
  EXPECT_NEAR(median(ratios), 0.45, 0.04);
  EXPECT_NEAR(t.volumeFraction, 0.2, 0.02);
}

// Aligned 3 : 1.5 : 1: summed over the particles, the second moments along x, y, z stand as the
// squared proportions (the random stretches of at most 1.25 average out over ~170 particles), and no
// particle is turned: its principal axes are the volume's.
TEST(ParticleTruth, AnisotropyAlignsTheParticles) {
  ParticleTruthOptions options = shapeTruth(TruthShape::Ellipsoid, 1.25, 1);
  options.anisotropy = {3, 1.5, 1};
  const ParticleTruth& t = truthOf(options);
  Eigen::Vector3d spread = Eigen::Vector3d::Zero();
  int aligned = 0, all = 0;
  for (const auto& voxels : particleVoxels(t)) {
    const Moments m = momentsOf(voxels);
    for (const Eigen::Vector3d& p : voxels) spread += (p - m.mean).cwiseAbs2();
    aligned += std::abs(m.axes.col(2).x()) > 0.99;  // the longest axis along x
    ++all;
  }
  ASSERT_GT(all, 100);
  EXPECT_NEAR(std::sqrt(spread.x() / spread.z()), 3.0, 0.3);
  EXPECT_NEAR(std::sqrt(spread.y() / spread.z()), 1.5, 0.15);
  EXPECT_GT(aligned, all * 9 / 10);
  EXPECT_NEAR(t.volumeFraction, 0.2, 0.02);
}

// The other two photos are the middle xz and yz sections, z down, in the class colours.
TEST(ParticleTruth, ThreeSectionsOneForEachPlane) {
  const ParticleTruthOptions options = smallTruth();
  const ParticleTruth& t = truthOf(options);
  const Dims& d = t.volume.dims;
  ASSERT_EQ(t.photoXz.size(), cv::Size(d.x, d.z));
  ASSERT_EQ(t.photoYz.size(), cv::Size(d.y, d.z));
  const auto colourAt = [&](int x, int y, int z) {
    const std::int32_t id = t.volume.particleId[d.index(x, y, z)];
    return id > 0 ? options.classes[std::size_t(t.classOf[std::size_t(id - 1)])].srgb
                  : options.backgroundSrgb;
  };
  for (int k = 0; k < d.z; ++k) {
    for (int i = 0; i < d.x; ++i)
      ASSERT_LT(cv::norm(t.photoXz.at<cv::Vec3f>(k, i) - colourAt(i, d.y / 2, k), cv::NORM_INF),
                0.06 + 5 * options.noise);
    for (int j = 0; j < d.y; ++j)
      ASSERT_LT(cv::norm(t.photoYz.at<cv::Vec3f>(k, j) - colourAt(d.x / 2, j, k), cv::NORM_INF),
                0.06 + 5 * options.noise);
  }
}

// A superellipsoid of exponent 4 fills about 0.81 of its box, an ellipsoid pi / 6 = 0.52; voxel
// rounding lowers both.
TEST(ParticleTruth, SuperellipsoidsAreBoxierThanEllipsoids) {
  const auto medianFill = [](TruthShape shape) {
    std::vector<double> fills;
    for (const auto& voxels : particleVoxels(truthOf(shapeTruth(shape, 1.5, 1))))
      fills.push_back(orientedBoxFill(voxels));
    return median(fills);
  };
  const double ellipsoid = medianFill(TruthShape::Ellipsoid),
               superellipsoid = medianFill(TruthShape::Superellipsoid);
  EXPECT_LT(ellipsoid, 0.55);
  EXPECT_GT(superellipsoid, ellipsoid + 0.12);
}

// Rounding at the surface costs a convex particle a few chord points; two balls fused at a waist
// (radius 6, centres 11 apart), the reference for "not convex", lose more than 5 %.
TEST(ParticleTruth, PolytopesAreConvex) {
  Rng rng(5);
  std::vector<Eigen::Vector3d> twoBalls;
  for (int k = -6; k <= 6; ++k)
    for (int j = -6; j <= 6; ++j)
      for (int i = -6; i <= 17; ++i)
        if (Eigen::Vector3d(i, j, k).norm() <= 6 || Eigen::Vector3d(i - 11, j, k).norm() <= 6)
          twoBalls.emplace_back(i, j, k);
  EXPECT_LT(chordShareInside(twoBalls, rng), 0.95);
  std::vector<double> shares;
  for (const auto& voxels : particleVoxels(truthOf(shapeTruth(TruthShape::Polytope, 1.25, 1))))
    shares.push_back(chordShareInside(voxels, rng));
  EXPECT_GT(*std::min_element(shares.begin(), shares.end()), 0.96);
  double mean = 0;
  for (double s : shares) mean += s / double(shares.size());
  EXPECT_GT(mean, 0.98);
}

// Blur softens the particles' edges before the noise, and the segmentation still finds them.
TEST(ParticleTruth, BlurSoftensThePhoto) {
  ParticleTruthOptions options = smallTruth();
  options.noise = 0;
  options.blur = 1.5;
  const ParticleTruth t = makeParticleTruth(options);
  int softened = 0;
  for (int j = 0; j < t.photo.rows; ++j)
    for (int i = 0; i < t.photo.cols; ++i)
      softened += cv::norm(t.photo.at<cv::Vec3f>(j, i) - options.backgroundSrgb, cv::NORM_INF) > 0.1 &&
                  t.volume.particleId[t.volume.dims.index(i, j, t.volume.dims.z / 2)] == 0;
  EXPECT_GT(softened, 100);
  const ExemplarStats stats = analyzeExemplar(t.photo, "truth", SegmentationOptions{});
  EXPECT_GT(stats.particles.size(), 20u);
}

TEST(ParticleTruth, SameSeedSameTruth) {
  for (TruthShape shape : {TruthShape::Ellipsoid, TruthShape::Superellipsoid, TruthShape::Polytope}) {
    ParticleTruthOptions options = smallTruth(shape);
    options.dims = {64, 64, 48};
    options.blur = 1;
    const ParticleTruth a = makeParticleTruth(options), b = makeParticleTruth(options);
    EXPECT_EQ(a.volume.particleId, b.volume.particleId);
    EXPECT_EQ(cv::norm(a.photo, b.photo, cv::NORM_INF), 0);
    options.seed = 4;
    EXPECT_NE(makeParticleTruth(options).volume.particleId, a.volume.particleId);
  }
}

TEST(ParticleTruth, RefusesOptionsItCannotMeet) {
  const std::vector<void (*)(ParticleTruthOptions&)> absurd = {
      [](ParticleTruthOptions& o) {
        o.classes[1].meanRadius = 30;
      },  // 60+ voxels long in a 64-voxel-deep volume
      [](ParticleTruthOptions& o) { o.shape = TruthShape::Polytope, o.classes[1].meanRadius = 14; },
      [](ParticleTruthOptions& o) { o.volumeFraction = 0.7; },
      [](ParticleTruthOptions& o) { o.classes.clear(); },
      [](ParticleTruthOptions& o) { o.classes[0].radiusSpread = 2; },
      [](ParticleTruthOptions& o) { o.classes[0].share = 0; },
      [](ParticleTruthOptions& o) { o.flatten = 0.1; },
      [](ParticleTruthOptions& o) { o.flatten = 1.5; },
      [](ParticleTruthOptions& o) { o.elongation = 5; },
      [](ParticleTruthOptions& o) { o.exponent = 0.5; },
      [](ParticleTruthOptions& o) { o.blur = -1; },
      [](ParticleTruthOptions& o) {
        o.anisotropy = {3, 1};
      },
      [](ParticleTruthOptions& o) {
        o.anisotropy = {3, 1, 0};
      },
      [](ParticleTruthOptions& o) {
        o.anisotropy = {12, 1, 1};
      },
      [](ParticleTruthOptions& o) {
        o.anisotropy = {1, 1, 10};
      },  // the large ones 146 voxels along z, 64 deep
      [](ParticleTruthOptions& o) {
        o.classes = {{1, 0, 1, {1, 1, 1}}}, o.dims = {1000, 1000, 1000};
      },  // 5 x 10^7 particles
  };
  for (std::size_t i = 0; i < absurd.size(); ++i) {
    ParticleTruthOptions options = smallTruth();
    absurd[i](options);
    EXPECT_THROW(makeParticleTruth(options), InputError) << "case " << i;
  }
  EXPECT_THROW(parseTruthShape("cube"), InputError);
  EXPECT_EQ(parseTruthShape("polytope"), TruthShape::Polytope);
}

}  // namespace
}  // namespace solidtex
