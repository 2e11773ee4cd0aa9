#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "io/imageIO.h"
#include "segmentation/analyzeExemplar.h"
#include "testHelpers.h"

namespace solidtex {
namespace {

using test::Disc;

// Two separate discs and a touching pair: four 8-connected components, five bodies.
const std::vector<Disc> kDiscs{
    {{40, 40}, 15, {}}, {{120, 50}, 20, {}}, {{70, 130}, 22, {}}, {{113, 130}, 22, {}}, {{190, 120}, 10, {}}};

cv::Mat noisePhoto(cv::Size size) {
  cv::Mat photo(size, CV_32FC3);
  cv::RNG(3).fill(photo, cv::RNG::UNIFORM, 0.0, 1.0);
  return photo;
}

SegmentationOptions withMask(const std::string& path, bool split) {
  SegmentationOptions options;
  options.maskPath = path;
  options.split = split;
  return options;
}

std::vector<int> componentAreas(const cv::Mat& mask) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  std::vector<int> areas;
  for (int i = 1; i < n; ++i) areas.push_back(stats.at<int>(i, cv::CC_STAT_AREA));
  std::sort(areas.begin(), areas.end());
  return areas;
}

cv::Mat paint(const ExemplarStats& stats, cv::Size size) {
  cv::Mat out = cv::Mat::zeros(size, CV_8UC1);
  for (const Particle2D& p : stats.particles) out(p.box).setTo(255, p.mask);
  return out;
}

class SegmentationMask : public ::testing::Test {
protected:
  void SetUp() override {
    mask_ = test::discMask(size_, kDiscs);
    path_ = (test::freshTempDir() / "mask.png").string();
    writeImage(path_, mask_);
  }
  const cv::Size size_{220, 170};
  cv::Mat mask_;
  std::string path_;
};

TEST_F(SegmentationMask, WithoutSplitGivesExactlyItsComponents) {
  const ExemplarStats stats = analyzeExemplar(noisePhoto(size_), "noise", withMask(path_, false));
  ASSERT_EQ(stats.particles.size(), 4u);
  std::vector<int> areas;
  for (const Particle2D& p : stats.particles) areas.push_back(int(p.area));
  std::sort(areas.begin(), areas.end());
  EXPECT_EQ(areas, componentAreas(mask_));
  EXPECT_EQ(cv::norm(paint(stats, size_), mask_, cv::NORM_INF), 0.0);
}

TEST_F(SegmentationMask, WithSplitCutsTouchingComponentsOnly) {
  const ExemplarStats stats = analyzeExemplar(noisePhoto(size_), "noise", withMask(path_, true));
  ASSERT_EQ(stats.particles.size(), 5u);
  EXPECT_EQ(cv::norm(paint(stats, size_), mask_, cv::NORM_INF), 0.0);
  double pair = 0;
  for (const Particle2D& p : stats.particles) {
    if (p.box.y < 100 || p.box.x > 150) continue;
    pair += p.area;
    EXPECT_NEAR(p.area, CV_PI * 22 * 22, 0.08 * CV_PI * 22 * 22);
  }
  EXPECT_EQ(pair, componentAreas(mask_)[3]);
}

TEST_F(SegmentationMask, InvertTakesTheBlackPart) {
  writeImage(path_, 255 - mask_);  // black discs on white
  SegmentationOptions options = withMask(path_, false);
  options.invert = true;
  const ExemplarStats stats = analyzeExemplar(noisePhoto(size_), "noise", options);
  ASSERT_EQ(stats.particles.size(), 4u);
  EXPECT_EQ(cv::norm(paint(stats, size_), mask_, cv::NORM_INF), 0.0);
}

TEST_F(SegmentationMask, MustMatchThePhotoSize) {
  EXPECT_THROW(analyzeExemplar(noisePhoto({200, 170}), "noise", withMask(path_, true)), InputError);
}

TEST_F(SegmentationMask, EmptyMaskMeansNoParticlesAndSaysSo) {
  writeImage(path_, cv::Mat::zeros(size_, CV_8UC1));
  try {
    analyzeExemplar(noisePhoto(size_), "noise", withMask(path_, true));
    FAIL() << "an all-black mask gave particles";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("the mask " + path_ + " has no white region"), std::string::npos) << message;
    EXPECT_EQ(message.find("give a mask"), std::string::npos) << message;
  }
}

TEST_F(SegmentationMask, MissingMaskFileIsAnInputError) {
  EXPECT_THROW(analyzeExemplar(noisePhoto(size_), "noise", withMask(path_ + ".gone.png", true)), InputError);
}

}  // namespace
}  // namespace solidtex
