#include "particles/fitHullSmoothing.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>
#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "common/distributionDistance.h"
#include "segmentation/regionShape.h"
#include "segmentation/resampleRegions.h"

namespace solidtex {
namespace {

constexpr double kMinShapeArea = 20;  // samples: smaller sections are too coarse to have a shape
constexpr int kHullsTried = 48;       // of the pool, smoothed per candidate
constexpr int kShapesPerCandidate = 96;
constexpr int kPlanesPerShape = 8;
constexpr std::uint64_t kFitStream = 0x736d6f6f;  // "smoo"

// The photo's statistical particles as the solid would show them: masks resampled to voxels.
ShapeColumns photoShapes(const ExemplarStats& stats, double voxelsPerPixel) {
  ShapeColumns out;
  for (std::size_t i : statisticalParticles(stats.particles)) {
    const Particle2D& p = stats.particles[i];
    std::vector<cv::Point> pixels;
    cv::findNonZero(resampleMask(p.mask, voxelsPerPixel), pixels);
    if (double(pixels.size()) >= kMinShapeArea) out.add(measureRegion(pixels));
  }
  return out;
}

// The shape's voxels in layer `layer` across `axis`, as pixels. The shapes are randomly turned, so
// an axis-aligned cut is a random section (aligned ones are cut across z, as their xy photo shows them), and
// it is sampled on the voxel grid as the photo's pixels are (an oblique sampling grid would add its own
// jagged edges).
std::vector<cv::Point> layerPixels(const VoxelShape& shape, int axis, int layer) {
  std::vector<cv::Point> pixels;
  const int extent[3] = {shape.dims.x, shape.dims.y, shape.dims.z};
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  int c[3];
  c[axis] = layer;
  for (c[b] = 0; c[b] < extent[b]; ++c[b])
    for (c[a] = 0; c[a] < extent[a]; ++c[a])
      if (shape.inside[shape.dims.index(c[0], c[1], c[2])]) pixels.emplace_back(c[a], c[b]);
  return pixels;
}

// Random sections of particles made at the photo's sizes times `sizeFactor`: a uniform offset
// across the shape, as a random plane meets a particle.
ShapeColumns sectionShapes(const ExemplarStats& stats, const ParticleFactory& factory, double voxelsPerPixel,
                           double sizeFactor, Rng& rng) {
  const std::vector<std::size_t> sources = statisticalParticles(stats.particles);
  const auto scaled = [&](int pixels) {
    return std::max(1, int(std::lround(pixels * voxelsPerPixel * sizeFactor)));
  };
  ShapeColumns out;
  for (int s = 0; s < kShapesPerCandidate && !sources.empty(); ++s) {
    const Particle2D& source = stats.particles[sources[uniformIndex(rng, sources.size())]];
    const ParticleSize size = factory.pickDepth(source.box.width, source.box.height, rng, source.phase);
    const VoxelShape shape = factory.make(scaled(size.width), scaled(size.height), scaled(size.depth), rng,
                                          factory.phaseOf(size.source));
    const int extent[3] = {shape.dims.x, shape.dims.y, shape.dims.z};
    for (int p = 0; p < kPlanesPerShape; ++p) {
      const int axis = factory.aligned() ? 2 : int(uniformIndex(rng, 3));  // aligned: as the xy photo
      const std::vector<cv::Point> pixels =
          layerPixels(shape, axis, int(uniformIndex(rng, std::uint64_t(extent[axis]))));
      if (double(pixels.size()) >= kMinShapeArea) out.add(measureRegion(pixels));
    }
  }
  return out;
}

}  // namespace

std::optional<double> parseSmoothing(const std::string& text) {
  if (text == "auto") return std::nullopt;
  std::size_t used = 0;
  double radius = -1;
  try {
    radius = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(radius >= 0 && radius <= 0.5))
    throw OptionError("--smoothing must be auto or a number from 0 to 0.5, got '" + text + "'");
  return radius;
}

std::vector<double> smoothingCandidates() { return {0, 0.02, 0.04, 0.06, 0.08, 0.1, 0.12, 0.16, 0.2}; }

SmoothingFit fitHullSmoothing(const ExemplarStats& stats, const ParticleFactory& factory,
                              double voxelsPerPixel, double sizeFactor, std::uint64_t seed) {
  const ShapeColumns photo = photoShapes(stats, voxelsPerPixel);
  const std::vector<double> radii = smoothingCandidates();
  std::vector<SmoothingFit> fits(radii.size());
  tbb::parallel_for(std::size_t(0), radii.size(), [&](std::size_t c) {
    HullSmoothing smoothing = factory.options().smoothing;
    smoothing.radius = radii[c];
    const ParticleFactory candidate = factory.withSmoothing(smoothing, kHullsTried);
    Rng rng(deriveSeed(seed, kFitStream));  // the same particles and planes for every candidate
    const ShapeColumns sections = sectionShapes(stats, candidate, voxelsPerPixel, sizeFactor, rng);
    fits[c] = {radii[c], ksStatistic(photo.solidity, sections.solidity),
               ksStatistic(photo.roundness, sections.roundness)};
  });
  return *std::min_element(fits.begin(), fits.end(), [](const SmoothingFit& a, const SmoothingFit& b) {
    return a.solidityKs + a.roundnessKs < b.solidityKs + b.roundnessKs;
  });
}

}  // namespace solidtex
