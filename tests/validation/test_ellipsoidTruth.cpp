#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "common/Error.h"
#include "segmentation/analyzeExemplar.h"
#include "validation/ellipsoidTruth.h"

namespace solidtex {
namespace {

EllipsoidTruthOptions smallTruth() {
  EllipsoidTruthOptions options;
  options.dims = {160, 160, 64};
  options.classes = {{4, 0.2, 0.75, {0.92f, 0.55f, 0.16f}}, {8, 0.15, 0.25, {0.25f, 0.48f, 0.88f}}};
  options.seed = 3;
  return options;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

class EllipsoidTruthTest : public testing::Test {
protected:
  static void SetUpTestSuite() { truth_ = new EllipsoidTruth(makeEllipsoidTruth(smallTruth())); }
  static void TearDownTestSuite() { delete truth_; }
  static EllipsoidTruth* truth_;
};
EllipsoidTruth* EllipsoidTruthTest::truth_ = nullptr;

TEST_F(EllipsoidTruthTest, FillsTheAskedFractionWithParticlesThatNeverTouch) {
  const EllipsoidTruth& t = *truth_;
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
                  t.volume.particleId[d.index((i + di + d.x) % d.x, (j + dj + d.y) % d.y, (k + dk + d.z) % d.z)];
              ASSERT_TRUE(other == 0 || other == id) << "particles " << id << " and " << other << " touch";
            }
      }
  EXPECT_EQ(counted, t.volumes);
}

// A particle of the large class holds 8x the volume of a small one on average.
TEST_F(EllipsoidTruthTest, ClassesHaveTheirSizesAndShares) {
  const EllipsoidTruth& t = *truth_;
  std::vector<double> small, large;
  for (std::size_t p = 0; p < t.volumes.size(); ++p) (t.classOf[p] == 0 ? small : large).push_back(t.volumes[p]);
  const double sphere4 = 4.0 / 3.0 * std::numbers::pi * 64, sphere8 = sphere4 * 8;
  EXPECT_NEAR(median(small) / sphere4, 1, 0.15);
  EXPECT_NEAR(median(large) / sphere8, 1, 0.15);
  EXPECT_NEAR(double(large.size()) / double(t.volumes.size()), 0.25, 0.05);
}

// The photo is the middle section: particle pixels in their class colour, background elsewhere, so
// segmenting it finds the section's particles and its area fraction.
TEST_F(EllipsoidTruthTest, PhotoIsTheMiddleSectionInClassColours) {
  const EllipsoidTruth& t = *truth_;
  const Dims& d = t.volume.dims;
  const EllipsoidTruthOptions options = smallTruth();
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

TEST(EllipsoidTruth, SameSeedSameTruth) {
  EllipsoidTruthOptions options = smallTruth();
  options.dims = {48, 48, 40};
  const EllipsoidTruth a = makeEllipsoidTruth(options), b = makeEllipsoidTruth(options);
  EXPECT_EQ(a.volume.particleId, b.volume.particleId);
  EXPECT_EQ(cv::norm(a.photo, b.photo, cv::NORM_INF), 0);
  options.seed = 4;
  EXPECT_NE(makeEllipsoidTruth(options).volume.particleId, a.volume.particleId);
}

TEST(EllipsoidTruth, RefusesOptionsItCannotMeet) {
  EllipsoidTruthOptions options = smallTruth();
  options.classes[1].meanRadius = 30;  // 60+ voxels long in a 48-voxel-deep volume
  EXPECT_THROW(makeEllipsoidTruth(options), InputError);
  options = smallTruth();
  options.volumeFraction = 0.7;
  EXPECT_THROW(makeEllipsoidTruth(options), InputError);
  options = smallTruth();
  options.classes.clear();
  EXPECT_THROW(makeEllipsoidTruth(options), InputError);
}

} // namespace
} // namespace solidtex
