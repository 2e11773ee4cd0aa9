#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "common/srgb.h"
#include "segmentation/analyzeExemplar.h"
#include "segmentation/detail/color.h"
#include "segmentation/detail/separateBackground.h"
#include "testHelpers.h"

namespace solidtex {
namespace {

using test::Disc;
using test::discPhoto;

const cv::Vec3f kPaper(0.85f, 0.82f, 0.78f);

std::vector<double> sortedAreas(const ExemplarStats& stats) {
  std::vector<double> areas;
  for (const Particle2D& p : stats.particles) areas.push_back(p.area);
  std::sort(areas.begin(), areas.end());
  return areas;
}

TEST(SegmentationSynthetic, DiscAreasMatchTheirRadii) {
  const std::vector<Disc> discs{{{70, 70}, 15, {0.7f, 0.1f, 0.1f}},
                                {{200, 90}, 20, {0.1f, 0.5f, 0.2f}},
                                {{120, 200}, 30, {0.2f, 0.2f, 0.7f}},
                                {{300, 200}, 25, {0.3f, 0.2f, 0.1f}}};
  const ExemplarStats stats = analyzeExemplar(discPhoto({400, 300}, kPaper, discs, 0.02), "discs", {});
  ASSERT_EQ(stats.particles.size(), discs.size());
  std::vector<double> expected;
  for (const Disc& d : discs) expected.push_back(CV_PI * d.radius * d.radius);
  std::sort(expected.begin(), expected.end());
  const std::vector<double> areas = sortedAreas(stats);
  for (std::size_t i = 0; i < areas.size(); ++i) EXPECT_NEAR(areas[i], expected[i], 0.03 * expected[i]) << i;
  for (const Particle2D& p : stats.particles) EXPECT_FALSE(p.border);
}

TEST(SegmentationSynthetic, ParticleColorIsTheLinearMean) {
  const cv::Vec3f red(0.8f, 0.2f, 0.1f);
  const ExemplarStats stats =
      analyzeExemplar(discPhoto({200, 160}, kPaper, {{{100, 80}, 30, red}}), "one", {});
  ASSERT_EQ(stats.particles.size(), 1u);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(stats.particles[0].color[c], srgbToLinear(red[c]), 1e-3);
    EXPECT_NEAR(stats.backgroundColor[c], srgbToLinear(kPaper[c]), 1e-3);
  }
}

TEST(SegmentationSynthetic, TouchingDiscsBecomeTwoParticles) {
  const std::vector<Disc> discs{{{100, 100}, 25, {0.6f, 0.1f, 0.1f}}, {{148, 100}, 25, {0.6f, 0.1f, 0.1f}}};
  const ExemplarStats stats = analyzeExemplar(discPhoto({260, 200}, kPaper, discs, 0.01), "pair", {});
  ASSERT_EQ(stats.particles.size(), 2u);
  for (const Particle2D& p : stats.particles) EXPECT_NEAR(p.area, CV_PI * 25 * 25, 0.08 * CV_PI * 25 * 25);
}

TEST(SegmentationSynthetic, TouchingDiscsStayOneWithoutSplit) {
  const std::vector<Disc> discs{{{100, 100}, 25, {0.6f, 0.1f, 0.1f}}, {{148, 100}, 25, {0.6f, 0.1f, 0.1f}}};
  SegmentationOptions options;
  options.split = false;
  const ExemplarStats stats = analyzeExemplar(discPhoto({260, 200}, kPaper, discs, 0.01), "pair", options);
  EXPECT_EQ(stats.particles.size(), 1u);
}

TEST(SegmentationSynthetic, ElongatedParticlesAreNotSplit) {
  cv::Mat photo = discPhoto({300, 240}, kPaper, {});
  cv::ellipse(photo, {150, 120}, {90, 18}, 30, 0, 360, cv::Scalar(0.2, 0.3, 0.6), cv::FILLED);
  cv::ellipse(photo, {60, 200}, {40, 14}, -10, 0, 360, cv::Scalar(0.2, 0.3, 0.6), cv::FILLED);
  const ExemplarStats stats = analyzeExemplar(photo, "ellipses", {});
  EXPECT_EQ(stats.particles.size(), 2u);
}

TEST(SegmentationSynthetic, FindsLightParticlesOnDarkAndDarkOnLight) {
  const std::vector<Disc> light{{{60, 60}, 20, {0.9f, 0.9f, 0.9f}},
                                {{150, 70}, 22, {0.85f, 0.85f, 0.85f}},
                                {{100, 150}, 18, {0.9f, 0.9f, 0.9f}}};
  EXPECT_EQ(analyzeExemplar(discPhoto({220, 200}, {0.15f, 0.15f, 0.15f}, light, 0.02), "light", {})
                .particles.size(),
            3u);
  std::vector<Disc> dark = light;
  for (Disc& d : dark) d.srgb = {0.1f, 0.1f, 0.1f};
  EXPECT_EQ(
      analyzeExemplar(discPhoto({220, 200}, {0.8f, 0.8f, 0.8f}, dark, 0.02), "dark", {}).particles.size(),
      3u);
}

TEST(SegmentationSynthetic, DenselyPackedParticlesAreTheParticles) {
  // Bright discs packed so they cover most of the image, touching their neighbours, with dark
  // gaps: the gaps, though fewer pixels, are the background.
  std::vector<Disc> discs;
  for (int row = 0; row < 5; ++row)
    for (int col = 0; col < 6; ++col)
      discs.push_back(
          {{float(30 + 38 * col + (row % 2) * 19), float(30 + 34 * row)}, 20, {0.75f, 0.72f, 0.7f}});
  const ExemplarStats stats =
      analyzeExemplar(discPhoto({270, 200}, {0.1f, 0.1f, 0.1f}, discs, 0.01), "packed", {});
  EXPECT_GT(stats.areaFraction, 0.5);
  EXPECT_EQ(stats.particles.size(), discs.size());
}

TEST(SegmentationSynthetic, UnevenLightingDoesNotHideParticles) {
  const std::vector<Disc> discs{{{50, 50}, 18, {0.9f, 0.9f, 0.9f}},
                                {{250, 50}, 18, {0.9f, 0.9f, 0.9f}},
                                {{50, 180}, 18, {0.9f, 0.9f, 0.9f}},
                                {{250, 180}, 18, {0.9f, 0.9f, 0.9f}},
                                {{150, 115}, 18, {0.9f, 0.9f, 0.9f}}};
  cv::Mat photo = discPhoto({300, 230}, {0, 0, 0}, {}, 0);
  for (int y = 0; y < photo.rows; ++y)
    for (int x = 0; x < photo.cols; ++x) {
      const float v = 0.1f + 0.45f * float(x + y) / float(photo.cols + photo.rows);  // 0.1 .. 0.55
      photo.at<cv::Vec3f>(y, x) = {v, v, v};
    }
  for (const Disc& d : discs)
    cv::circle(photo, d.centre, int(d.radius), cv::Scalar(0.9, 0.9, 0.9), cv::FILLED);
  const ExemplarStats stats = analyzeExemplar(photo, "ramp", {});
  ASSERT_EQ(stats.particles.size(), discs.size());
  for (const Particle2D& p : stats.particles) EXPECT_NEAR(p.area, CV_PI * 18 * 18, 0.05 * CV_PI * 18 * 18);
}

TEST(SegmentationSynthetic, BorderParticlesAreFlaggedAndLeftOutOfTheHistogram) {
  const std::vector<Disc> discs{{{5, 80}, 20, {0.2f, 0.2f, 0.6f}},
                                {{100, 80}, 20, {0.2f, 0.2f, 0.6f}},
                                {{170, 60}, 14, {0.2f, 0.2f, 0.6f}}};
  const ExemplarStats stats = analyzeExemplar(discPhoto({220, 160}, kPaper, discs), "border", {});
  ASSERT_EQ(stats.particles.size(), 3u);
  int border = 0, histogramTotal = 0;
  for (const Particle2D& p : stats.particles) border += p.border;
  for (int c : stats.histogram.counts) histogramTotal += c;
  EXPECT_EQ(border, 1);
  EXPECT_EQ(histogramTotal, 2);
  EXPECT_TRUE(stats.particles[0].border || stats.particles[1].border || stats.particles[2].border);
  for (const Particle2D& p : stats.particles) EXPECT_EQ(p.border, p.box.x == 0);
}

TEST(SegmentationSynthetic, InvertSwapsTheClasses) {
  const std::vector<Disc> discs{{{60, 60}, 20, {0.1f, 0.1f, 0.1f}}, {{150, 100}, 25, {0.1f, 0.1f, 0.1f}}};
  const cv::Mat linear = segmentation::detail::srgbToLinear(discPhoto({220, 180}, kPaper, discs, 0.01));
  const cv::Mat normal = segmentation::detail::separateBackground(linear, 8, false);
  const cv::Mat inverted = segmentation::detail::separateBackground(linear, 8, true);
  EXPECT_EQ(cv::countNonZero(normal & inverted), 0);
  EXPECT_EQ(cv::countNonZero(normal | inverted), int(normal.total()));

  // The paper becomes the one particle; its outline encloses the discs, so it covers everything.
  SegmentationOptions options;
  options.invert = true;
  options.split = false;
  const ExemplarStats stats =
      analyzeExemplar(discPhoto({220, 180}, kPaper, discs, 0.01), "inverted", options);
  ASSERT_EQ(stats.particles.size(), 1u);
  EXPECT_TRUE(stats.particles[0].border);
  EXPECT_DOUBLE_EQ(stats.areaFraction, 1.0);
}

TEST(SegmentationSynthetic, SmallSpecksAreDroppedByDefault) {
  const std::vector<Disc> discs{{{60, 60}, 20, {0.1f, 0.1f, 0.1f}}, {{150, 100}, 1, {0.1f, 0.1f, 0.1f}}};
  const cv::Mat photo = discPhoto({220, 180}, kPaper, discs);
  EXPECT_EQ(analyzeExemplar(photo, "specks", {}).particles.size(), 1u);
  SegmentationOptions keepAll;
  keepAll.minArea = 0;
  EXPECT_EQ(analyzeExemplar(photo, "specks", keepAll).particles.size(), 2u);
}

TEST(SegmentationSynthetic, FlatImageHasNoParticles) {
  const cv::Mat grey(100, 120, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  try {
    analyzeExemplar(grey, "grey.png", {});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("grey.png: no particles found"), std::string::npos) << e.what();
  }
}

TEST(SegmentationSynthetic, FaintNoiseHasNoParticles) {
  EXPECT_THROW(analyzeExemplar(discPhoto({120, 100}, {0.5f, 0.5f, 0.5f}, {}, 0.005), "noise", {}),
               InputError);
}

TEST(SegmentationSynthetic, IsDeterministic) {
  std::vector<Disc> discs;
  for (int i = 0; i < 12; ++i)
    discs.push_back(
        {{float(30 + 45 * (i % 6)), float(40 + 60 * (i / 6))}, 12.0f + float(i % 4) * 3, {0.3f, 0.6f, 0.2f}});
  const cv::Mat photo = discPhoto({300, 200}, kPaper, discs, 0.03);
  const ExemplarStats a = analyzeExemplar(photo, "det", {});
  const ExemplarStats b = analyzeExemplar(photo, "det", {});
  ASSERT_EQ(a.particles.size(), b.particles.size());
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    EXPECT_EQ(a.particles[i].id, int(i) + 1);
    EXPECT_EQ(a.particles[i].box, b.particles[i].box);
    EXPECT_EQ(a.particles[i].area, b.particles[i].area);
    EXPECT_EQ(a.particles[i].contour, b.particles[i].contour);
  }
}

TEST(SegmentationSynthetic, RejectsWrongPhotoTypes) {
  EXPECT_THROW(analyzeExemplar(cv::Mat(50, 50, CV_8UC3, cv::Scalar(0)), "bytes", {}), InputError);
  EXPECT_THROW(analyzeExemplar(cv::Mat(4, 50, CV_32FC3, cv::Scalar(0)), "thin", {}), InputError);
}

}  // namespace
}  // namespace solidtex
