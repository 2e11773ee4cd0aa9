#include <gtest/gtest.h>

#include <cmath>

#include "common/Error.h"
#include "discStats.h"
#include "placement/sectionSizing.h"

namespace solidtex {
namespace {

// Spheres of class j, largest section area A = edges[j+1], cut by random planes: the plane's distance
// h from the centre is uniform in [0, R], so a section's area a = A (1 - h^2/R^2) has the CDF
// 1 - sqrt(1 - a/A), and a sphere is cut as often as its diameter, in proportion to sqrt(A).
Eigen::MatrixXd sphereKernel(const std::vector<double>& edges) {
  const Eigen::Index n = Eigen::Index(edges.size()) - 1;
  Eigen::MatrixXd kernel = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double largest = edges[std::size_t(j + 1)];
    const auto cdf = [&](double a) { return 1 - std::sqrt(1 - std::min(a, largest) / largest); };
    for (Eigen::Index i = 0; i <= j; ++i)
      kernel(i, j) = std::sqrt(largest) * (cdf(edges[std::size_t(i + 1)]) - cdf(edges[std::size_t(i)]));
  }
  return kernel;
}

// A smooth two-sized 3D distribution seen through its sections unfolds back to itself, although the
// sections' own distribution is far from it (small sections come mostly from large particles).
TEST(UnfoldSections, RecoversASmoothDistributionBehindSphereSections) {
  constexpr int n = 16;
  std::vector<double> edges;
  for (int c = 0; c <= n; ++c) edges.push_back(10 * std::pow(100.0, double(c) / n));
  const Eigen::MatrixXd kernel = sphereKernel(edges);
  Eigen::VectorXd truth(n);
  for (int c = 0; c < n; ++c)  // two sizes, as in a mix of fine and coarse grains
    truth[c] = std::exp(-0.5 * std::pow((c - 5.0) / 1.2, 2)) + 0.4 * std::exp(-0.5 * std::pow(c - 12.0, 2));
  truth /= truth.sum();
  Eigen::VectorXd sections = kernel * truth;
  sections /= sections.sum();
  const Eigen::VectorXd unfolded = unfoldSections(kernel, sections);
  EXPECT_NEAR(unfolded.sum(), 1, 1e-12);
  const auto cdfGap = [&](const Eigen::VectorXd& x) {
    double gap = 0, a = 0, b = 0;
    for (int c = 0; c < n; ++c) gap = std::max(gap, std::abs((a += x[c]) - (b += truth[c])));
    return gap;
  };
  // The smoothing that keeps counting noise out costs a little sharpness; the sections are far off.
  EXPECT_LT(cdfGap(unfolded), 0.05);
  EXPECT_GT(cdfGap(sections), 0.15);
}

TEST(UnfoldSections, ClassesNothingWasMadeForGetNoShare) {
  Eigen::MatrixXd kernel = Eigen::MatrixXd::Identity(3, 3);
  kernel(1, 1) = 0;
  const Eigen::VectorXd unfolded = unfoldSections(kernel, Eigen::Vector3d(0.5, 0.2, 0.3));
  EXPECT_EQ(unfolded[1], 0);
  EXPECT_NEAR(unfolded.sum(), 1, 1e-12);
}

// A class the photo shows one section in three of still counts (a 10:1 size mix holds many such
// small particles); one shown one time in ten is left out: the photo cannot count it.
TEST(SectionKernel, LeavesOutOnlyClassesThePhotoHardlyShows) {
  AreaClasses classes;
  classes.edges = {10, 20, 40};
  std::vector<SectionSample> samples;
  for (int i = 0; i < 30; ++i) {
    samples.push_back({0, i % 3 == 0 ? 15.0 : 5.0, 2, 20});   // a third at or above minArea 10
    samples.push_back({1, i % 10 == 0 ? 30.0 : 5.0, 4, 80});  // a tenth
  }
  const Eigen::MatrixXd kernel = sectionKernel(samples, classes, 10, 1);
  EXPECT_NEAR(kernel(0, 0), 2.0 / 3, 1e-12);  // a third of the sections, each cut with chance 2
  EXPECT_EQ(kernel.col(1).sum(), 0);
}

TEST(AreaClasses, SpanThePhotosAreasEvenlyInLogArea) {
  ExemplarStats stats;
  stats.minArea = 8;
  for (double area : {40.0, 160.0, 640.0, 2560.0}) {
    Particle2D p;
    p.area = area;
    p.box = cv::Rect(0, 0, 10, 10);
    stats.particles.push_back(p);
  }
  stats.particles[3].border = true;  // left out, as the histogram leaves it out
  const AreaClasses classes = areaClassesOf(stats, 4);
  ASSERT_EQ(classes.count(), 4);
  EXPECT_DOUBLE_EQ(classes.edges.front(), 20);
  EXPECT_DOUBLE_EQ(classes.edges.back(), 640);
  EXPECT_NEAR(classes.edges[1] / classes.edges[0], classes.edges[4] / classes.edges[3], 1e-9);
  EXPECT_EQ(classes.classOf, (std::vector<int>{0, 2, 3, -1}));
  EXPECT_EQ(classes.classOfArea(10), -1);
  EXPECT_EQ(classes.classOfArea(1e6), 3);
}

// The band of the 3D volume CDF: a CDF from 0 to 1 over its log-spaced volumes, the 5 % curve
// never above the 95 % one, and the fit's own CDF not below the band: the fit takes the smallest
// good size factor (the smallest particles), the band's resamples any good one.
TEST(FitSectionSizing, GivesABandOfTheVolumeCdf) {
  const ExemplarStats stats = test::discStats(test::kDiscs, 0.25);
  const ParticleFactory factory(stats, test::fewShapes());
  const SectionSizing sizing = fitSectionSizing(stats, factory, 1.0, 3, 40);
  const SizingUncertainty& u = sizing.uncertainty;
  ASSERT_EQ(u.bandVolumes.size(), 32u);
  ASSERT_EQ(u.bandLow.size(), 32u);
  ASSERT_EQ(u.bandHigh.size(), 32u);
  EXPECT_DOUBLE_EQ(u.bandCdf.front(), 0);
  EXPECT_NEAR(u.bandCdf.back(), 1, 1e-9);
  for (std::size_t i = 0; i < u.bandVolumes.size(); ++i) {
    if (i > 0) {
      EXPECT_GT(u.bandVolumes[i], u.bandVolumes[i - 1]);
      EXPECT_GE(u.bandCdf[i], u.bandCdf[i - 1] - 1e-12);
      EXPECT_GE(u.bandLow[i], u.bandLow[i - 1] - 1e-12);
    }
    EXPECT_LE(u.bandLow[i], u.bandHigh[i]);
    EXPECT_GE(u.bandCdf[i], u.bandLow[i] - 0.02);
  }
}

TEST(Sizing, ParsesNames) {
  EXPECT_EQ(parseSizing("bbox"), Sizing::Bbox);
  EXPECT_EQ(parseSizing(sizingName(Sizing::Sections)), Sizing::Sections);
  EXPECT_THROW(parseSizing("volume"), InputError);
}

}  // namespace
}  // namespace solidtex
