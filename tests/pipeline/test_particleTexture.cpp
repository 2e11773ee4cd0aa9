#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "common/srgb.h"
#include "io/imageIO.h"
#include "io/vdbIO.h"
#include "pipeline/particleSolidJob.h"
#include "tests/scratchPath.h"

namespace solidtex {
namespace {

namespace fs = std::filesystem;

// Discs of one tone with a coarse grain inside, on a flat grey: the particles have a texture of
// their own. One tone, so that the grain's spread does not hang on which discs a small solid holds.
cv::Mat grainyDiscsPhoto() {
  const cv::Size size(256, 256);
  cv::Mat photo(size, CV_32FC3, cv::Scalar::all(0.45));
  cv::RNG rng(13);
  cv::Mat grain(size, CV_32F), grain3;
  rng.fill(grain, cv::RNG::NORMAL, 0, 0.08);
  cv::GaussianBlur(grain, grain, {0, 0}, 0.8);
  cv::cvtColor(grain, grain3, cv::COLOR_GRAY2RGB);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const cv::Point centre(16 + 32 * x + rng.uniform(-3, 4), 16 + 32 * y + rng.uniform(-3, 4));
      cv::Mat disc = cv::Mat::zeros(size, CV_8U);
      cv::circle(disc, centre, rng.uniform(9, 13), 255, cv::FILLED);
      cv::Mat(cv::Mat(size, CV_32FC3, cv::Scalar(0.75, 0.62, 0.45)) + grain3).copyTo(photo, disc);
    }
  cv::min(cv::max(photo, 0.0), 1.0, photo);
  return photo;
}

double luminance(const std::array<float, 3>& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

// Inside the particles: the spread of luminance about each particle's mean, and the mean squared
// step to the next voxel of the same particle along x, y and z.
struct InsideGrain {
  double spread = 0;
  std::array<double, 3> step{};
};

InsideGrain insideGrain(const SolidVolume& volume) {
  const Dims& d = volume.dims;
  std::vector<double> sum, count;
  for (std::size_t i = 0; i < volume.color.size(); ++i) {
    const std::size_t id = std::size_t(volume.particleId[i]);
    if (id == 0) continue;
    if (id >= sum.size()) sum.resize(id + 1), count.resize(id + 1);
    sum[id] += luminance(volume.color[i]), count[id] += 1;
  }
  InsideGrain g;
  double squares = 0, n = 0;
  std::array<double, 3> steps{}, stepCounts{};
  for (int z = 0; z + 1 < d.z; ++z)
    for (int y = 0; y + 1 < d.y; ++y)
      for (int x = 0; x + 1 < d.x; ++x) {
        const std::size_t i = d.index(x, y, z);
        const std::int32_t id = volume.particleId[i];
        if (id == 0) continue;
        const double l = luminance(volume.color[i]);
        squares += std::pow(l - sum[std::size_t(id)] / count[std::size_t(id)], 2), n += 1;
        const std::size_t next[3] = {d.index(x + 1, y, z), d.index(x, y + 1, z), d.index(x, y, z + 1)};
        for (int a = 0; a < 3; ++a) {
          if (volume.particleId[next[a]] != id) continue;
          steps[std::size_t(a)] += std::pow(luminance(volume.color[next[a]]) - l, 2);
          stepCounts[std::size_t(a)] += 1;
        }
      }
  g.spread = std::sqrt(squares / n);
  for (int a = 0; a < 3; ++a) g.step[std::size_t(a)] = steps[std::size_t(a)] / stepCounts[std::size_t(a)];
  return g;
}

InsideGrain solidInsides(Texture texture, const fs::path& photoPath, nlohmann::json& report) {
  const fs::path output =
      test::scratchPath("pipeline_test", std::string("discs-") + textureName(texture) + ".vdb");
  ParticleSolidJob job;
  job.photo = photoPath.string();
  job.output = output.string();
  job.dims = {64, 64, 64};
  job.voxelsPerPixel = 1;  // the photo's grain at its own scale
  job.particleTexture = texture;
  job.progress = false;
  report = runParticleSolid(job);
  const InsideGrain grain = insideGrain(readVdb(output.string()));
  fs::remove(output);
  return grain;
}

// The photo's discs measured the same way in the plane (their grain, linear luminance).
InsideGrain photoInsides(const cv::Mat& srgb) {
  cv::Mat linear(srgb.size(), CV_32F);
  for (int y = 0; y < srgb.rows; ++y)
    for (int x = 0; x < srgb.cols; ++x) {
      const cv::Vec3f c = srgb.at<cv::Vec3f>(y, x);
      linear.at<float>(y, x) = float(luminance({srgbToLinear(c[0]), srgbToLinear(c[1]), srgbToLinear(c[2])}));
    }
  const float background = linear.at<float>(0, 0);
  cv::Mat disc = cv::abs(linear - background) > 1e-4f, labels;
  cv::erode(disc, disc, cv::Mat());  // the outlines' mixed pixels are not grain
  const int discs = cv::connectedComponents(disc, labels, 4);
  std::vector<double> sum(std::size_t(discs), 0), count(std::size_t(discs), 0);
  for (int y = 0; y < srgb.rows; ++y)
    for (int x = 0; x < srgb.cols; ++x)
      if (const int id = labels.at<int>(y, x))
        sum[std::size_t(id)] += linear.at<float>(y, x), count[std::size_t(id)]++;
  InsideGrain g;
  double squares = 0, n = 0, steps = 0, stepCount = 0;
  for (int y = 0; y + 1 < srgb.rows; ++y)
    for (int x = 0; x + 1 < srgb.cols; ++x) {
      const int id = labels.at<int>(y, x);
      if (id == 0) continue;
      const double l = linear.at<float>(y, x);
      squares += std::pow(l - sum[std::size_t(id)] / count[std::size_t(id)], 2), n += 1;
      for (const cv::Point next : {cv::Point(x + 1, y), cv::Point(x, y + 1)})
        if (labels.at<int>(next) == id) steps += std::pow(linear.at<float>(next) - l, 2), stepCount += 1;
    }
  g.spread = std::sqrt(squares / n);
  g.step.fill(steps / stepCount);
  return g;
}

// The synthesised insides have the photo's grain, alike along the three axes; the projected ones
// (the paper's) lay each particle's pixels along one oblique direction, which smooths the grain
// along some axes more than others: stripes on every slice but one.
TEST(ParticleTexture, SynthesizedInsidesHaveThePhotosGrainInEveryDirection) {
  const cv::Mat photo = grainyDiscsPhoto();
  const fs::path photoPath = test::scratchPath("pipeline_test", "grainy-discs.png");
  writeImage(photoPath.string(), photo);
  const InsideGrain truth = photoInsides(photo);

  nlohmann::json report;
  const InsideGrain synthesized = solidInsides(Texture::Synthesized, photoPath, report);
  EXPECT_EQ(report["particle_texture"]["texture"], "synthesized");
  EXPECT_NEAR(synthesized.spread / truth.spread, 1.0, 0.3);
  const auto worst = [&](const InsideGrain& g) {
    double off = 0;
    for (double step : g.step) off = std::max(off, std::abs(step / truth.step[0] - 1));
    return off;
  };
  EXPECT_LT(worst(synthesized), 0.35);

  const InsideGrain projected = solidInsides(Texture::Projected, photoPath, report);
  EXPECT_EQ(report["particle_texture"]["texture"], "projected");
  EXPECT_LT(worst(synthesized), worst(projected));
  fs::remove(photoPath);
}

}  // namespace
}  // namespace solidtex
