#include <gtest/gtest.h>

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "segmentation/analyzeExemplar.h"
#include "segmentation/textureExemplars.h"

namespace solidtex {
namespace {

// Red discs in a grey grain: the exemplar keeps the grain and nothing of the discs.
TEST(MatrixExemplar, FillsTheParticlesWithTheMatrixGrain) {
  const cv::Size size(160, 160);
  cv::RNG rng(3);
  cv::Mat grain(size, CV_32F), photo(size, CV_32FC3);
  rng.fill(grain, cv::RNG::NORMAL, 0.5, 0.08);
  cv::cvtColor(grain, photo, cv::COLOR_GRAY2RGB);
  for (int i = 0; i < 30; ++i)
    cv::circle(photo, {rng.uniform(0, size.width), rng.uniform(0, size.height)}, rng.uniform(6, 12),
               cv::Scalar(0.85, 0.1, 0.1), cv::FILLED);
  cv::min(cv::max(photo, 0.0), 1.0, photo);
  const ExemplarStats stats = analyzeExemplar(photo, "red on grey", {});

  const cv::Mat exemplar = matrixExemplar(stats);
  ASSERT_EQ(exemplar.size(), cv::Size(64, 64));
  cv::Mat channels[3];
  cv::split(exemplar, channels);
  double mostRed = 0;
  cv::minMaxLoc(channels[0] - channels[1], nullptr, &mostRed);
  EXPECT_LT(mostRed, 0.1);  // grey to within the 8-bit Lab round trip
  cv::Scalar mean, spread;
  cv::meanStdDev(channels[1], mean, spread);
  EXPECT_NEAR(mean[0], 0.5, 0.03);
  EXPECT_NEAR(spread[0] / 0.08, 1.0, 0.25);

  TextureExemplarOptions tooMuch;
  tooMuch.minShare = 0.99;
  EXPECT_TRUE(matrixExemplar(stats, tooMuch).empty());
}

// A window of matrix alone has nothing to fill and is kept as it is.
TEST(MatrixExemplar, AWindowOfMatrixAloneIsKeptAsItIs) {
  cv::Mat photo(120, 200, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  cv::RNG rng(5);
  cv::Mat grain(photo.size(), CV_32FC3);
  rng.fill(grain, cv::RNG::NORMAL, 0, 0.05);
  photo += grain;
  for (int i = 0; i < 6; ++i)
    cv::circle(photo, {150 + (i % 2) * 25, 15 + i * 18}, 8, cv::Scalar(0.9, 0.2, 0.1), cv::FILLED);
  cv::min(cv::max(photo, 0.0), 1.0, photo);
  const ExemplarStats stats = analyzeExemplar(photo, "discs at the right", {});
  const cv::Mat exemplar = matrixExemplar(stats);
  ASSERT_EQ(exemplar.size(), cv::Size(64, 64));
  cv::Scalar mean = cv::mean(exemplar);
  EXPECT_NEAR(mean[0], mean[1], 0.02);
}

// Red and blue discs, each with a grain, on flat grey: the exemplar keeps the grain and drops the
// discs' colours (their residuals about grey), and the matrix between them is filled with that grain.
TEST(ParticleExemplar, KeepsTheParticlesGrainWithoutTheirColours) {
  const cv::Size size(160, 160);
  cv::Mat photo(size, CV_32FC3, cv::Scalar::all(0.4));
  cv::RNG rng(11);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const cv::Point centre(20 + 40 * x, 20 + 40 * y);
      const cv::Scalar colour = (x + y) % 2 ? cv::Scalar(0.8, 0.15, 0.1) : cv::Scalar(0.1, 0.2, 0.75);
      cv::Mat disc = cv::Mat::zeros(size, CV_8U), grain(size, CV_32F), grain3;
      cv::circle(disc, centre, 17, 255, cv::FILLED);
      rng.fill(grain, cv::RNG::NORMAL, 0, 0.06);
      cv::cvtColor(grain, grain3, cv::COLOR_GRAY2RGB);
      cv::Mat(cv::Mat(size, CV_32FC3, colour) + grain3).copyTo(photo, disc);
    }
  cv::min(cv::max(photo, 0.0), 1.0, photo);
  const ExemplarStats stats = analyzeExemplar(photo, "grainy discs", {});
  ASSERT_EQ(stats.particles.size(), 16u);

  const cv::Mat exemplar = particleExemplar(stats);
  ASSERT_EQ(exemplar.size(), cv::Size(64, 64));
  // The particles' residuals pooled (linear; the grain was added in sRGB, so each tone and channel
  // has its own), against the exemplar's spread about linear 0.5 = sRGB 0.735, where the sRGB
  // curve's slope is 0.66.
  cv::Scalar squares = cv::Scalar::all(0);
  double area = 0;
  for (const Particle2D& particle : stats.particles) {
    cv::Mat square;
    cv::multiply(particle.residual, particle.residual, square);
    squares += cv::sum(square), area += particle.area;
  }
  cv::Mat channels[3];
  cv::split(exemplar, channels);
  for (int c = 0; c < 3; ++c) {
    cv::Scalar mean, spread;
    cv::meanStdDev(channels[c], mean, spread);
    EXPECT_NEAR(mean[0], 0.735, 0.03) << "channel " << c;  // no disc's colour
    EXPECT_NEAR(spread[0] / (0.66 * std::sqrt(squares[c] / area)), 1.0, 0.3) << "channel " << c;
  }

  TextureExemplarOptions tooMuch;
  tooMuch.minShare = 0.99;
  EXPECT_TRUE(particleExemplar(stats, tooMuch).empty());
}

}  // namespace
}  // namespace solidtex
