#include "segmentation/analyzeExemplar.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "common/Error.h"
#include "segmentation/detail/color.h"
#include "segmentation/detail/fillHoles.h"
#include "segmentation/detail/loadMask.h"
#include "segmentation/detail/measureParticles.h"
#include "segmentation/detail/separateBackground.h"
#include "segmentation/detail/splitParticles.h"
#include "segmentation/detail/summarize.h"
#include "segmentation/imageIO.h"

namespace solidtex {
namespace {

// Default noise filter (paper 3.2): a particle must cover at least 1/10000 of the photo, and never
// fewer than 8 pixels, so speckle is dropped at any resolution while the small particles of a
// small photo survive.
constexpr double kMinAreaFraction = 1e-4;
constexpr double kMinAreaFloor = 8;

double minAreaFor(const cv::Size& size, const SegmentationOptions& options) {
  if (options.minArea >= 0) return options.minArea;
  return std::max(kMinAreaFloor, kMinAreaFraction * double(size.area()));
}

cv::Mat particleMask(const cv::Mat& linear, const SegmentationOptions& options, double minArea) {
  if (!options.maskPath) return detail::separateBackground(linear, minArea, options.invert);
  cv::Mat mask = detail::loadMask(*options.maskPath, linear.size());
  return options.invert ? cv::Mat(mask == 0) : mask;
}

void checkPhoto(const cv::Mat& photo, const std::string& name) {
  if (photo.type() != CV_32FC3) throw InputError(name + ": photo must be CV_32FC3 sRGB");
  if (photo.cols < kMinPhotoSide || photo.rows < kMinPhotoSide)
    throw InputError(name + ": photo is too small to segment");
}

}  // namespace

ExemplarStats analyzeExemplar(const cv::Mat& photoSrgb, const std::string& name,
                              const SegmentationOptions& options) {
  checkPhoto(photoSrgb, name);
  const double minArea = minAreaFor(photoSrgb.size(), options);
  const cv::Mat linear = detail::srgbToLinear(photoSrgb);
  cv::Mat labels = detail::labelParticles(particleMask(linear, options, minArea), options.split);
  detail::fillEnclosedHoles(labels);

  ExemplarStats stats;
  stats.name = name;
  stats.imageWidth = photoSrgb.cols;
  stats.imageHeight = photoSrgb.rows;
  stats.minArea = minArea;
  stats.particles = detail::measureParticles(labels, linear, minArea);
  if (stats.particles.empty())
    throw InputError(
        name + ": no particles found (nothing of at least " + std::to_string(int(std::ceil(minArea))) +
        " pixels stands out from the background; give a mask, white = particle, or a smaller minimum area)");
  detail::measureBackground(stats, linear);
  std::vector<const Particle2D*> counted;
  for (std::size_t i : statisticalParticles(stats.particles)) counted.push_back(&stats.particles[i]);
  stats.histogram = detail::buildAreaHistogram(counted);
  stats.sizePairs = detail::buildSizePairs(counted);
  return stats;
}

ExemplarStats analyzeExemplar(const std::string& path, const SegmentationOptions& options) {
  return analyzeExemplar(loadPhoto(path), std::filesystem::path(path).filename().string(), options);
}

}  // namespace solidtex
