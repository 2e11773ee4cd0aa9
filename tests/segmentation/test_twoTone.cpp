#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "segmentation/analyzeExemplar.h"

namespace solidtex {
namespace {

// A photo as pebbles in mortar look: touching discs, light and dark by turns, each shaded by light
// from the upper left with a highlight and its own speckle, on a mortar of fine grain and blotches.
struct PebblePhoto {
  cv::Mat srgb;   // CV_32FC3
  cv::Mat mask;   // CV_8U, 255 on pebbles
  int inner = 0;  // pebbles clear of the border
};

cv::Mat textureNoise(cv::Size size, cv::RNG& rng, double grain, double blotch) {
  cv::Mat fine(size, CV_32F), coarse(size, CV_32F);
  rng.fill(fine, cv::RNG::NORMAL, 0, grain);
  rng.fill(coarse, cv::RNG::NORMAL, 0, 1);
  cv::GaussianBlur(coarse, coarse, {0, 0}, 4);
  return fine + coarse * (blotch / 0.07);  // a sigma-4 blur leaves unit noise a spread of 0.07
}

std::vector<cv::Vec3f> placeDiscs(cv::Size size, cv::RNG& rng) {
  std::vector<cv::Vec3f> discs;  // x, y, radius
  for (int attempt = 0; attempt < 4000 && discs.size() < 90; ++attempt) {
    const cv::Vec3f d(rng.uniform(0.f, float(size.width)), rng.uniform(0.f, float(size.height)),
                      rng.uniform(9.f, 16.f));
    // Overlapping by up to 8 % of the radii: they touch along short flat contacts, as packed pebbles.
    const bool free = std::none_of(discs.begin(), discs.end(), [&](const cv::Vec3f& o) {
      return std::hypot(d[0] - o[0], d[1] - o[1]) < 0.92f * (d[2] + o[2]);
    });
    if (free) discs.push_back(d);
  }
  return discs;
}

PebblePhoto pebblePhoto(cv::Size size, std::uint64_t seed) {
  cv::RNG rng(seed);
  const cv::Mat mortarGrain = textureNoise(size, rng, 14.0 / 255, 10.0 / 255);
  PebblePhoto photo;
  photo.srgb.create(size, CV_32FC3);
  photo.mask = cv::Mat::zeros(size, CV_8U);
  const cv::Vec3f mortar(150.f / 255, 138.f / 255, 118.f / 255);
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x)
      photo.srgb.at<cv::Vec3f>(y, x) = mortar + cv::Vec3f::all(mortarGrain.at<float>(y, x));
  const cv::Vec3f tones[2] = {{215.f / 255, 205.f / 255, 190.f / 255}, {75.f / 255, 62.f / 255, 55.f / 255}};
  const std::vector<cv::Vec3f> discs = placeDiscs(size, rng);
  for (std::size_t i = 0; i < discs.size(); ++i) {
    const cv::Vec3f& d = discs[i];
    const bool inner =
        d[0] - d[2] > 0 && d[1] - d[2] > 0 && d[0] + d[2] < size.width && d[1] + d[2] < size.height;
    photo.inner += inner;
    for (int y = std::max(0, int(d[1] - d[2]) - 1); y <= std::min(size.height - 1, int(d[1] + d[2]) + 1); ++y)
      for (int x = std::max(0, int(d[0] - d[2]) - 1); x <= std::min(size.width - 1, int(d[0] + d[2]) + 1);
           ++x) {
        const float nx = (float(x) - d[0]) / d[2], ny = (float(y) - d[1]) / d[2];
        if (nx * nx + ny * ny > 1) continue;
        const float shade = 0.925f + 0.125f * std::clamp(-(nx + ny) / 1.4f, -1.f, 1.f);
        const float highlight =
            40.f / 255 * std::exp(-((nx + 0.4f) * (nx + 0.4f) + (ny + 0.4f) * (ny + 0.4f)) / 0.04f);
        const float speckle = float(rng.gaussian(6.0 / 255));
        photo.srgb.at<cv::Vec3f>(y, x) = tones[i % 2] * shade + cv::Vec3f::all(highlight + speckle);
        photo.mask.at<uchar>(y, x) = 255;
      }
  }
  cv::min(cv::max(photo.srgb, 0.0), 1.0, photo.srgb);
  return photo;
}

int innerParticles(const ExemplarStats& stats) {
  return int(std::count_if(stats.particles.begin(), stats.particles.end(),
                           [](const Particle2D& p) { return !p.border; }));
}

// Light and dark pebbles both stand out from the mortar between them, and touching pebbles come
// apart, on photos drawn with three seeds.
TEST(SegmentationTwoTone, FindsEveryPebbleOfBothTonesOnTexturedMortar) {
  for (std::uint64_t seed : {1, 2, 3}) {
    const PebblePhoto photo = pebblePhoto({256, 256}, seed);
    const ExemplarStats stats = analyzeExemplar(photo.srgb, "pebbles", {});
    const double trueFraction = cv::countNonZero(photo.mask) / double(photo.mask.total());
    EXPECT_NEAR(innerParticles(stats), photo.inner, 0.05 * photo.inner) << "seed " << seed;
    EXPECT_NEAR(stats.areaFraction, trueFraction, 0.03) << "seed " << seed;
  }
}

}  // namespace
}  // namespace solidtex
