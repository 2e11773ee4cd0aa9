#include "segmentation/analyzeExemplar.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "io/imageIO.h"
#include "segmentation/detail/color.h"
#include "segmentation/detail/fillHoles.h"
#include "segmentation/detail/halfMaximumOutlines.h"
#include "segmentation/detail/loadMask.h"
#include "segmentation/detail/measureParticles.h"
#include "segmentation/detail/morphology.h"
#include "segmentation/detail/outlineBlur.h"
#include "segmentation/detail/separateBackground.h"
#include "segmentation/detail/splitParticles.h"
#include "segmentation/detail/summarize.h"

namespace solidtex {
namespace {

// Default noise filter (paper 3.2): a particle must cover at least 1/10000 of the photo, and never
// fewer than 8 pixels, so speckle is dropped at any resolution while the small particles of a
// small photo survive.
constexpr double kMinAreaFraction = 1e-4;
constexpr double kMinAreaFloor = 8;
// Outlines are redrawn half-way up their edges by default only on a background plain enough for
// the edge to be a blurred step: its smoothed colour distance wanders by at most this share of the
// particles' contrast.
constexpr double kPlainBackground = 0.1;
// Under 4 pixels a region has no outline to speak of, whatever the photo: noise.
constexpr double kNoiseArea = 4;
// A region under an eighth of the photo's typical particle is a speck beside it.
constexpr double kTypicalShare = 1.0 / 8;

// Areas of the labelled particles of at least kNoiseArea pixels.
std::vector<int> particleAreas(const cv::Mat& labels) {
  double most = 0;
  cv::minMaxLoc(labels, nullptr, &most);
  std::vector<int> counts(std::size_t(most) + 1, 0);
  for (int r = 0; r < labels.rows; ++r)
    for (const int* label = labels.ptr<int>(r); label != labels.ptr<int>(r) + labels.cols; ++label)
      ++counts[std::size_t(*label)];
  std::vector<int> areas;
  for (std::size_t label = 1; label < counts.size(); ++label)
    if (counts[label] >= kNoiseArea) areas.push_back(counts[label]);
  return areas;
}

// The area at which half of the particles' pixels lie in particles at least as large: the photo's
// typical particle, which many specks of noise do not move.
double typicalArea(std::vector<int> areas) {
  std::sort(areas.begin(), areas.end(), std::greater<>());
  const double total = std::accumulate(areas.begin(), areas.end(), 0.0);
  double covered = 0;
  for (const int area : areas)
    if ((covered += area) >= total / 2) return area;
  return 0;
}

// The photo-size default, unless the particles under it hold most of what stands out (a photo of many
// small particles): then an eighth of the typical particle, at least the noise floor.
double defaultMinArea(const cv::Size& size, const std::vector<int>& areasAtNoise) {
  const double byPhoto = std::max(kMinAreaFloor, kMinAreaFraction * double(size.area()));
  double all = 0, under = 0;
  for (const int area : areasAtNoise) {
    all += area;
    if (area < byPhoto) under += area;
  }
  if (under <= 0.5 * all) return byPhoto;
  return std::clamp(kTypicalShare * typicalArea(areasAtNoise), kNoiseArea, byPhoto);
}

bool hasUserMask(const SegmentationOptions& options) { return !options.mask.empty() || options.maskPath; }

cv::Mat userMask(const SegmentationOptions& options, const cv::Size& photoSize) {
  if (options.mask.empty()) return segmentation::detail::loadMask(*options.maskPath, photoSize);
  if (options.mask.type() != CV_8UC1) throw InputError("mask must be CV_8U (one 8-bit channel)");
  segmentation::detail::checkMaskSize(options.mask.size(), photoSize, "mask");
  return options.mask != 0;
}

struct ParticleMask {
  cv::Mat mask;  // CV_8U, 255 on particles
  double outlineBlur = 0;
  bool halfMaximum = false;
};

// Outlines redrawn half-way up their edges when asked, or by default when they look blurred;
// otherwise the corners the segmentation's median rounded are put back.
void drawOutlines(ParticleMask& particles, const cv::Mat& linear, const SegmentationOptions& options,
                  double minArea) {
  namespace detail = segmentation::detail;
  const cv::Mat background = particles.mask == 0;
  if (cv::countNonZero(particles.mask) == 0 || cv::countNonZero(background) == 0) return;
  const cv::Mat lab = detail::linearToLab(linear);
  const cv::Mat distance = detail::colourDistance(lab, background);
  cv::Mat denoised;
  cv::medianBlur(distance, denoised, 3);
  particles.outlineBlur = detail::measureOutlineBlur(denoised, particles.mask);
  particles.halfMaximum =
      particles.outlineBlur > 0 &&
      (options.outlines == OutlineMethod::HalfMaximum ||
       (options.outlines == OutlineMethod::Auto && particles.outlineBlur >= kBlurredOutline));
  if (particles.halfMaximum) {
    const double plainBackground =
        options.outlines == OutlineMethod::Auto ? kPlainBackground : std::numeric_limits<double>::infinity();
    cv::Mat outlined =
        detail::halfMaximumOutlines(lab, particles.mask, particles.outlineBlur, plainBackground);
    particles.halfMaximum = !outlined.empty();
    if (particles.halfMaximum) {
      particles.mask = std::move(outlined);
      detail::removeSmallComponents(particles.mask, minArea);
      detail::fillSmallHoles(particles.mask, minArea);
      return;
    }
  }
  detail::restoreCorners(particles.mask, detail::crossMedian(distance));
}

ParticleMask particleMask(const cv::Mat& linear, const SegmentationOptions& options, double minArea) {
  if (hasUserMask(options)) {
    cv::Mat mask = userMask(options, linear.size());
    return {options.invert ? cv::Mat(mask == 0) : mask};
  }
  ParticleMask particles{segmentation::detail::separateBackground(linear, minArea, options.invert)};
  drawOutlines(particles, linear, options, minArea);
  return particles;
}

void checkPhoto(const cv::Mat& photo, const std::string& name) {
  if (photo.type() != CV_32FC3) throw InputError(name + ": photo must be CV_32FC3 sRGB");
  if (photo.cols < kMinPhotoSide || photo.rows < kMinPhotoSide)
    throw InputError(name + ": photo is too small to segment");
}

std::string noParticlesMessage(const ExemplarStats& stats, const SegmentationOptions& options) {
  const std::string minimum = std::to_string(int(std::ceil(stats.minArea))) + " pixels";
  const std::string dropped = stats.regionsBelowMinArea > 0
                                  ? "; " + std::to_string(stats.regionsBelowMinArea) +
                                        " smaller regions were dropped (see --min-area)"
                                  : "";
  if (hasUserMask(options))
    return stats.name + ": no particles found: the mask " +
           (options.mask.empty() ? *options.maskPath + " " : "") + "has no white region of at least " +
           minimum + dropped;
  if (stats.regionsBelowMinArea > 0)
    return stats.name + ": no particles found: the " + std::to_string(stats.regionsBelowMinArea) +
           " regions that stand out from the background are all smaller than " + minimum +
           " (see --min-area)";
  return stats.name + ": no particles found: nothing stands out from the background (give a mask, " +
         "white = particle)";
}

}  // namespace

OutlineMethod parseOutlineMethod(const std::string& name) {
  if (name == "auto") return OutlineMethod::Auto;
  if (name == "watershed") return OutlineMethod::Watershed;
  if (name == "half-maximum") return OutlineMethod::HalfMaximum;
  throw OptionError("unknown outlines '" + name + "': use auto, watershed or half-maximum");
}

ExemplarStats analyzeExemplar(const cv::Mat& photoSrgb, const std::string& name,
                              const SegmentationOptions& options) {
  checkPhoto(photoSrgb, name);
  const cv::Mat linear = segmentation::detail::srgbToLinear(photoSrgb);
  ParticleMask particles = particleMask(linear, options, kNoiseArea);
  const cv::Mat labelsAtNoise = segmentation::detail::labelParticles(particles.mask, options.split);
  const std::vector<int> areasAtNoise = particleAreas(labelsAtNoise);

  ExemplarStats stats;
  stats.name = name;
  stats.imageWidth = photoSrgb.cols;
  stats.imageHeight = photoSrgb.rows;
  stats.minArea = options.minArea >= 0 ? options.minArea : defaultMinArea(photoSrgb.size(), areasAtNoise);
  double standingOut = 0, dropped = 0;
  for (const int area : areasAtNoise) {
    standingOut += area;
    if (area < stats.minArea) {
      dropped += area;
      ++stats.regionsBelowMinArea;
    }
  }
  stats.areaShareBelowMinArea = standingOut > 0 ? dropped / standingOut : 0;
  if (stats.minArea != kNoiseArea && !hasUserMask(options))
    particles = particleMask(linear, options, stats.minArea);
  cv::Mat labels = stats.minArea == kNoiseArea || hasUserMask(options)
                       ? labelsAtNoise
                       : segmentation::detail::labelParticles(particles.mask, options.split);
  stats.outlineBlur = particles.outlineBlur;
  stats.halfMaximumOutlines = particles.halfMaximum;
  segmentation::detail::fillEnclosedHoles(labels);
  stats.particles = segmentation::detail::measureParticles(labels, linear, stats.minArea);
  if (stats.particles.empty()) throw InputError(noParticlesMessage(stats, options));
  segmentation::detail::measureBackground(stats, linear);
  std::vector<const Particle2D*> counted;
  for (std::size_t i : statisticalParticles(stats.particles)) counted.push_back(&stats.particles[i]);
  stats.histogram = segmentation::detail::buildAreaHistogram(counted);
  stats.sizePairs = segmentation::detail::buildSizePairs(counted);
  return stats;
}

cv::Mat maskFromImage(const cv::Mat& imageSrgb) {
  cv::Mat grey;
  cv::cvtColor(imageSrgb, grey, cv::COLOR_RGB2GRAY);
  return grey > 0.5f;
}

ExemplarStats analyzeExemplar(const std::string& path, const SegmentationOptions& options) {
  return analyzeExemplar(loadPhoto(path), std::filesystem::path(path).filename().string(), options);
}

}  // namespace solidtex
