#include "particles/fitHullSmoothing.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "common/distributionDistance.h"
#include "particles/parseAutoOrNumber.h"
#include "particles/sectionShapes.h"

namespace solidtex {
namespace {

constexpr int kHullsTried = 48;  // of the pool, smoothed per candidate
constexpr int kShapesPerCandidate = 96;
constexpr int kPlanesPerShape = 8;
constexpr std::uint64_t kFitStream = 0x736d6f6f;  // "smoo"

}  // namespace

std::optional<double> parseSmoothing(const std::string& text) {
  return parseAutoOrNumber(text, "--smoothing", 0, 0.5);
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
    const ShapeColumns sections =
        sectionShapes(stats, candidate, voxelsPerPixel, sizeFactor, kShapesPerCandidate, kPlanesPerShape,
                      SectionAxis::Uniform, rng);
    fits[c] = {radii[c], ksStatistic(photo.solidity, sections.solidity),
               ksStatistic(photo.roundness, sections.roundness)};
  });
  return *std::min_element(fits.begin(), fits.end(), [](const SmoothingFit& a, const SmoothingFit& b) {
    return a.solidityKs + a.roundnessKs < b.solidityKs + b.roundnessKs;
  });
}

}  // namespace solidtex
