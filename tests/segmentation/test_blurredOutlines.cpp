#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "segmentation/analyzeExemplar.h"
#include "segmentation/detail/outlineBlur.h"
#include "segmentation/regionShape.h"
#include "testHelpers.h"

namespace solidtex {
namespace {

using test::Disc;

const cv::Vec3f kDarkGround(0.16f, 0.16f, 0.17f);
const cv::Vec3f kOrange(0.92f, 0.55f, 0.16f);

// 36 discs of radius 6 to 13 on a 6 x 6 grid, none touching.
std::vector<Disc> gridOfDiscs(const cv::Vec3f& colour) {
  std::vector<Disc> discs;
  for (int row = 0; row < 6; ++row)
    for (int col = 0; col < 6; ++col)
      discs.push_back({{20.f + 34 * col, 20.f + 34 * row}, 6.f + float((row * 6 + col) % 8), colour});
  return discs;
}

// The discs' photo blurred by a lens of `blur` pixels, then the sensor's noise.
cv::Mat blurredPhoto(const std::vector<Disc>& discs, double blur, double noise) {
  cv::Mat photo = test::discPhoto({210, 210}, kDarkGround, discs);
  if (blur > 0) cv::GaussianBlur(photo, photo, {0, 0}, blur);
  cv::Mat grain(photo.size(), CV_32FC3);
  cv::RNG rng(7);
  rng.fill(grain, cv::RNG::NORMAL, 0.0, noise);
  cv::min(cv::max(photo + grain, 0.0), 1.0, photo);
  return photo;
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
  return values[values.size() / 2];
}

RegionShape shapeOf(const Particle2D& particle) {
  std::vector<cv::Point> pixels;
  cv::findNonZero(particle.mask, pixels);
  for (cv::Point& p : pixels) p += particle.box.tl();
  return measureRegion(pixels);
}

std::vector<double> solidities(const ExemplarStats& stats) {
  std::vector<double> values;
  for (const Particle2D& p : stats.particles) values.push_back(shapeOf(p).solidity);
  return values;
}

// Each particle's area over the area of the disc it lies on.
std::vector<double> areaRatios(const ExemplarStats& stats, const std::vector<Disc>& discs) {
  std::vector<double> ratios;
  for (const Particle2D& p : stats.particles) {
    const cv::Point2d centre = shapeOf(p).centroid;
    const auto nearest = std::min_element(discs.begin(), discs.end(), [&](const Disc& a, const Disc& b) {
      return cv::norm(cv::Point2d(a.centre) - centre) < cv::norm(cv::Point2d(b.centre) - centre);
    });
    ratios.push_back(p.area / (CV_PI * nearest->radius * nearest->radius));
  }
  return ratios;
}

TEST(OutlineBlur, MeasuresTheSigmaOfABlurredStep) {
  const cv::Size size(210, 210);
  const cv::Mat step = test::discMask(size, gridOfDiscs(kOrange));
  for (const double sigma : {0.0, 1.0, 2.0, 3.0}) {
    cv::Mat distance;
    step.convertTo(distance, CV_32F, 60.0 / 255);
    if (sigma > 0) cv::GaussianBlur(distance, distance, {0, 0}, sigma);
    const double blur = segmentation::detail::measureOutlineBlur(distance, distance > 30);
    // A sharp step measures the half-pixel ramp that sampling between pixels makes (0.37); a blur of
    // 3 reads low, as the profile's levels, 3.5-5 pixels out, are then still on the ramp.
    if (sigma == 0)
      EXPECT_LT(blur, 0.5);
    else if (sigma < 3)
      EXPECT_NEAR(blur, sigma, 0.1 * sigma) << sigma;
    else
      EXPECT_NEAR(blur, sigma, 0.2 * sigma);
  }
}

TEST(OutlineBlur, NoContrastNoMeasure) {
  const cv::Mat flat(64, 64, CV_32F, cv::Scalar(3.0));
  cv::Mat half = cv::Mat::zeros(64, 64, CV_8U);
  half.colRange(0, 32).setTo(255);
  EXPECT_EQ(segmentation::detail::measureOutlineBlur(flat, half), 0.0);
}

// A blurred, noisy photo: the watershed's outlines wander along the shallow edges (ragged, less
// solid than the discs), the half-maximum outlines follow the discs as the sharp photo's do.
TEST(HalfMaximumOutlines, FollowTheDiscsOfABlurredNoisyPhoto) {
  const std::vector<Disc> discs = gridOfDiscs(kOrange);
  const ExemplarStats sharp = analyzeExemplar(blurredPhoto(discs, 0, 0.02), "sharp", {});
  const ExemplarStats blurred = analyzeExemplar(blurredPhoto(discs, 2, 0.05), "blurred", {});
  SegmentationOptions watershed;
  watershed.outlines = OutlineMethod::Watershed;
  const ExemplarStats ragged = analyzeExemplar(blurredPhoto(discs, 2, 0.05), "blurred", watershed);

  EXPECT_FALSE(sharp.halfMaximumOutlines);
  EXPECT_LT(sharp.outlineBlur, 0.6);
  EXPECT_TRUE(blurred.halfMaximumOutlines);
  EXPECT_FALSE(ragged.halfMaximumOutlines);
  // Blurred in sRGB, measured on the colour distance (not linear in sRGB): within 15 %.
  EXPECT_NEAR(blurred.outlineBlur, 2.0, 0.3);
  ASSERT_EQ(blurred.particles.size(), discs.size());
  ASSERT_EQ(sharp.particles.size(), discs.size());

  // The sharp photo's segmentation is the reference: digital discs' solidity, their areas.
  const double sharpSolidity = median(solidities(sharp));
  EXPECT_NEAR(median(solidities(blurred)), sharpSolidity, 0.01);
  EXPECT_LT(median(solidities(ragged)), sharpSolidity - 0.02);
  // Orange on a dark ground, blurred in sRGB: the colour distance is half-way a little inside the
  // edge, and the outlines come out up to 15 % small on the smallest discs (radius 6).
  for (const double ratio : areaRatios(blurred, discs)) EXPECT_NEAR(ratio, 0.95, 0.1);
  EXPECT_NEAR(median(areaRatios(blurred, discs)), median(areaRatios(sharp, discs)), 0.08);
}

TEST(HalfMaximumOutlines, CanBeAskedForOrRefused) {
  const std::vector<Disc> discs = gridOfDiscs(kOrange);
  SegmentationOptions options;
  options.outlines = OutlineMethod::HalfMaximum;
  const ExemplarStats asked = analyzeExemplar(blurredPhoto(discs, 0, 0.02), "sharp", options);
  EXPECT_TRUE(asked.halfMaximumOutlines);
  EXPECT_EQ(asked.particles.size(), discs.size());
  EXPECT_EQ(parseOutlineMethod("watershed"), OutlineMethod::Watershed);
  EXPECT_THROW(parseOutlineMethod("sharp"), OptionError);
}

}  // namespace
}  // namespace solidtex
