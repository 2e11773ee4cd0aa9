#include "validation/continuousQuality.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <string>

#include "common/Error.h"
#include "common/Random.h"
#include "common/secondsSince.h"
#include "validation/patchDistances.h"
#include "validation/slicePatches.h"

namespace solidtex {
namespace {

void checkInputs(const SolidVolume& solid, const cv::Mat& exemplar, const cv::Mat& reference,
                 const ContinuousQualityOptions& o) {
  if (exemplar.empty() || exemplar.type() != CV_32FC3)
    throw InputError("the exemplar must be a 3-channel float sRGB image");
  if (!reference.empty() && reference.type() != CV_32FC3)
    throw InputError("the reference must be a 3-channel float sRGB image");
  if (solid.color.empty() || solid.color.size() != solid.dims.count())
    throw InputError("the solid has no color grid covering its box");
  const auto positive = [](int v) { return v > 0; };
  if (o.similaritySide <= 0 || !std::all_of(o.distanceSides.begin(), o.distanceSides.end(), positive) ||
      o.scales.empty() || !std::all_of(o.scales.begin(), o.scales.end(), positive) || o.patches <= 0 ||
      o.queries <= 0 || o.directions <= 0 || o.histogramBins <= 0)
    throw InputError("patch sides, scales and counts must be positive");
}

// One patch size and scale: the exemplar's patches and the sets compared with them.
struct PatchSets {
  Eigen::MatrixXf exemplar, axis, oblique, reference;
};

std::optional<PatchSets> samplePatchSets(const SrgbVolume& volume, const cv::Mat& exemplar,
                                         const cv::Mat& reference, PatchGeometry g, std::uint64_t seed) {
  std::int64_t count =
      std::min(std::int64_t(std::numeric_limits<int>::max()), patchPositions(exemplar.size(), g));
  if (!reference.empty()) count = std::min(count, patchPositions(reference.size(), g));
  if (count <= 0 || !axisPatchesFit(volume.dims, g) || !obliquePatchesFit(volume.dims, g))
    return std::nullopt;
  const int n = int(count);
  PatchSets sets;
  sets.exemplar = imagePatches(exemplar, g, n, deriveSeed(seed, 0));
  sets.axis = axisSlicePatches(volume, g, n, deriveSeed(seed, 1));
  sets.oblique = obliqueSlicePatches(volume, g, n, deriveSeed(seed, 2));
  if (!reference.empty()) sets.reference = imagePatches(reference, g, n, deriveSeed(seed, 3));
  return sets;
}

// Coherence and completeness of `patches` against the exemplar's, from `queries` random patches of each
// (both sets are in random order).
void addSimilarity(const Eigen::MatrixXf& patches, const Eigen::MatrixXf& exemplar, int queries,
                   PatchSimilarity& into) {
  const Eigen::Index q = std::min<Eigen::Index>(queries, patches.cols());
  into.coherence += meanNearestPatchDistance(patches.leftCols(q), exemplar);
  into.completeness += meanNearestPatchDistance(exemplar.leftCols(q), patches);
}

void addDistance(const Eigen::MatrixXf& patches, const Eigen::MatrixXf& exemplar, PatchGeometry g,
                 int directions, std::uint64_t seed, PatchSimilarity& into) {
  into.patchDistances.push_back(
      {g.side, g.scale, int(patches.cols()), slicedWasserstein(patches, exemplar, directions, seed)});
}

void average(PatchSimilarity& s, int similarityScales) {
  s.coherence /= similarityScales;
  s.completeness /= similarityScales;
  double sum = 0;
  for (const PatchDistance& d : s.patchDistances) sum += d.distance;
  s.patchDistance = s.patchDistances.empty() ? 0.0 : sum / double(s.patchDistances.size());
}

std::optional<PositionHistogramStats> positionsOf(const SolidVolume& solid, const cv::Size& exemplar) {
  if (solid.sourcePosition.empty()) return std::nullopt;
  std::vector<std::int32_t> sources(solid.sourcePosition.size());
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const long x = std::lround(solid.sourcePosition[i][0]), y = std::lround(solid.sourcePosition[i][1]);
    // Positions beyond this exemplar: the solid was made from another one.
    if (x < 0 || y < 0 || x >= exemplar.width || y >= exemplar.height) return std::nullopt;
    sources[i] = std::int32_t(y * exemplar.width + x);
  }
  return positionHistogramStats(sources, exemplar.area());
}

}  // namespace

ContinuousQuality measureContinuousSolid(const SolidVolume& solid, const cv::Mat& exemplarImage,
                                         const cv::Mat& referenceImage, const ContinuousQualityOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  checkInputs(solid, exemplarImage, referenceImage, o);
  const cv::Mat exemplar = exemplarImage.clone(), reference = referenceImage.clone();  // continuous
  const SrgbVolume volume = srgbVolumeOf(solid);
  std::set<int> sides(o.distanceSides.begin(), o.distanceSides.end());
  sides.insert(o.similaritySide);

  ContinuousQuality q;
  if (!reference.empty()) q.reference.emplace();
  int similarityScales = 0;
  for (int side : sides)
    for (int scale : o.scales) {
      const PatchGeometry g{side, scale};
      const std::uint64_t seed = deriveSeed(o.seed, std::uint64_t(side), std::uint64_t(scale));
      const std::optional<PatchSets> sets = samplePatchSets(volume, exemplar, reference, g, seed);
      if (!sets) continue;
      if (side == o.similaritySide) {
        ++similarityScales;
        addSimilarity(sets->axis, sets->exemplar, o.queries, q.axis);
        addSimilarity(sets->oblique, sets->exemplar, o.queries, q.oblique);
        if (q.reference) addSimilarity(sets->reference, sets->exemplar, o.queries, *q.reference);
      }
      if (std::find(o.distanceSides.begin(), o.distanceSides.end(), side) == o.distanceSides.end()) continue;
      const std::uint64_t directions = deriveSeed(seed, 4);
      addDistance(sets->axis, sets->exemplar, g, o.directions, directions, q.axis);
      addDistance(sets->oblique, sets->exemplar, g, o.directions, directions, q.oblique);
      if (q.reference)
        addDistance(sets->reference, sets->exemplar, g, o.directions, directions, *q.reference);
    }
  if (similarityScales == 0)
    throw InputError("the solid and the photos are too small for " + std::to_string(o.similaritySide) +
                     " x " + std::to_string(o.similaritySide) + " patches on oblique slices");
  average(q.axis, similarityScales);
  average(q.oblique, similarityScales);
  if (q.reference) average(*q.reference, similarityScales);

  const auto* exemplarColors = exemplar.ptr<float>();
  const std::size_t exemplarPixels = exemplar.total();
  q.colorHistogramDistance = colorHistogramDistance(volume.rgb.data(), volume.dims.count(), exemplarColors,
                                                    exemplarPixels, o.histogramBins);
  if (!reference.empty())
    q.referenceColorHistogramDistance = colorHistogramDistance(
        reference.ptr<float>(), reference.total(), exemplarColors, exemplarPixels, o.histogramBins);
  q.positions = positionsOf(solid, exemplar.size());
  q.seconds = secondsSince(start);
  return q;
}

double colorHistogramDistance(const float* a, std::size_t countA, const float* b, std::size_t countB,
                              int bins) {
  const std::size_t cells = std::size_t(bins) * bins * bins;
  auto histogram = [&](const float* rgb, std::size_t count) {
    std::vector<double> h(cells, 0.0);
    for (std::size_t i = 0; i < count; ++i) {
      std::size_t cell = 0;
      for (int k = 0; k < 3; ++k)
        cell = cell * bins + std::size_t(std::clamp(int(rgb[3 * i + k] * float(bins)), 0, bins - 1));
      h[cell] += 1.0 / double(std::max<std::size_t>(count, 1));
    }
    return h;
  };
  const std::vector<double> ha = histogram(a, countA), hb = histogram(b, countB);
  double tv = 0;
  for (std::size_t i = 0; i < cells; ++i) tv += std::abs(ha[i] - hb[i]);
  return 0.5 * tv;
}

PositionHistogramStats positionHistogramStats(const std::vector<std::int32_t>& sources, int pixels) {
  PositionHistogramStats s;
  if (pixels <= 0) return s;
  std::vector<std::int64_t> h(std::size_t(pixels), 0);
  std::int64_t total = 0;
  for (std::int32_t p : sources)
    if (p >= 0 && p < pixels) {
      ++h[std::size_t(p)];
      ++total;
    }
  if (total == 0) return s;
  std::int64_t used = 0;
  double entropy = 0, sq = 0;
  const double mean = double(total) / pixels;
  for (std::int64_t c : h) {
    if (c > 0) {
      ++used;
      const double p = double(c) / double(total);
      entropy -= p * std::log(p);
    }
    sq += (double(c) - mean) * (double(c) - mean);
  }
  s.coverage = double(used) / pixels;
  s.flatness = pixels > 1 ? entropy / std::log(double(pixels)) : 1.0;
  s.variation = std::sqrt(sq / pixels) / mean;
  return s;
}

}  // namespace solidtex
