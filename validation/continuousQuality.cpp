#include "validation/continuousQuality.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <string>

#include "common/Error.h"
#include "common/Random.h"
#include "common/secondsSince.h"
#include "validation/patchDistances.h"
#include "validation/slicePatches.h"

namespace solidtex {
namespace {

void checkOptions(const cv::Mat& exemplar, const cv::Mat& reference, const ContinuousQualityOptions& o) {
  if (exemplar.empty() || exemplar.type() != CV_32FC3)
    throw InputError("the exemplar must be a 3-channel float sRGB image");
  if (!reference.empty() && reference.type() != CV_32FC3)
    throw InputError("the reference must be a 3-channel float sRGB image");
  const auto positive = [](int v) { return v > 0; };
  if (o.similaritySide <= 0 || !std::all_of(o.distanceSides.begin(), o.distanceSides.end(), positive) ||
      o.scales.empty() || !std::all_of(o.scales.begin(), o.scales.end(), positive) || o.patches <= 0 ||
      o.queries <= 0 || o.directions <= 0 || o.histogramBins <= 0)
    throw InputError("patch sides, scales and counts must be positive");
  if (o.planeAxis < -1 || o.planeAxis > 2) throw InputError("the plane's axis must be 0, 1, 2 or -1 for all");
}

// Where compared patches come from: a solid's axis or oblique slices, an image.
struct PatchSource {
  std::function<std::int64_t(PatchGeometry)> positions;  ///< how many patches it holds (0: none fit)
  std::function<Eigen::MatrixXf(PatchGeometry, int, std::uint64_t)> sample;
};

PatchSource imageSource(const cv::Mat& image) {
  return {[&image](PatchGeometry g) { return patchPositions(image.size(), g); },
          [&image](PatchGeometry g, int n, std::uint64_t seed) { return imagePatches(image, g, n, seed); }};
}

PatchSource sliceSource(const SrgbVolume& volume, bool oblique, int planeAxis) {
  return {[&volume, oblique](PatchGeometry g) {
            const bool fits = oblique ? obliquePatchesFit(volume.dims, g) : axisPatchesFit(volume.dims, g);
            return fits ? std::int64_t(std::numeric_limits<int>::max()) : std::int64_t(0);
          },
          [&volume, oblique, planeAxis](PatchGeometry g, int n, std::uint64_t seed) {
            return oblique ? obliqueSlicePatches(volume, g, n, seed)
                           : axisSlicePatches(volume, g, n, seed, planeAxis);
          }};
}

// Coherence and completeness of `patches` against the exemplar's, from `queries` random patches of each
// (both sets are in random order).
void addSimilarity(const Eigen::MatrixXf& patches, const Eigen::MatrixXf& exemplar, int queries,
                   PatchSimilarity& into) {
  const Eigen::Index q = std::min<Eigen::Index>(queries, patches.cols());
  into.coherence += meanNearestPatchDistance(patches.leftCols(q), exemplar);
  into.completeness += meanNearestPatchDistance(exemplar.leftCols(q), patches);
}

void average(PatchSimilarity& s, int similarityScales) {
  s.coherence /= similarityScales;
  s.completeness /= similarityScales;
  double sum = 0;
  for (const PatchDistance& d : s.patchDistances) sum += d.distance;
  s.patchDistance = s.patchDistances.empty() ? 0.0 : sum / double(s.patchDistances.size());
}

// Every source against the exemplar, at every patch side and scale where all of them and the exemplar
// hold patches, with the same number of patches from each.
std::vector<PatchSimilarity> comparePatchSources(const std::vector<PatchSource>& sources,
                                                 const cv::Mat& exemplar, const ContinuousQualityOptions& o) {
  std::set<int> sides(o.distanceSides.begin(), o.distanceSides.end());
  sides.insert(o.similaritySide);
  std::vector<PatchSimilarity> out(sources.size());
  int similarityScales = 0;
  for (int side : sides)
    for (int scale : o.scales) {
      const PatchGeometry g{side, scale};
      std::int64_t count = std::min<std::int64_t>(o.patches, patchPositions(exemplar.size(), g));
      for (const PatchSource& source : sources) count = std::min(count, source.positions(g));
      if (count <= 0) continue;
      const std::uint64_t seed = deriveSeed(o.seed, std::uint64_t(side), std::uint64_t(scale));
      const Eigen::MatrixXf reference = imagePatches(exemplar, g, int(count), deriveSeed(seed, 0));
      const bool similarity = side == o.similaritySide;
      const bool distance =
          std::find(o.distanceSides.begin(), o.distanceSides.end(), side) != o.distanceSides.end();
      similarityScales += similarity;
      for (std::size_t s = 0; s < sources.size(); ++s) {
        const Eigen::MatrixXf patches = sources[s].sample(g, int(count), deriveSeed(seed, s + 1));
        if (similarity) addSimilarity(patches, reference, o.queries, out[s]);
        if (distance)
          out[s].patchDistances.push_back(
              {side, scale, int(count),
               slicedWasserstein(patches, reference, o.directions, deriveSeed(seed, 4))});
      }
    }
  if (similarityScales == 0)
    throw InputError("the solid or image and the photos are too small for " +
                     std::to_string(o.similaritySide) + " x " + std::to_string(o.similaritySide) +
                     " patches");
  for (PatchSimilarity& s : out) average(s, similarityScales);
  return out;
}

double colorDistance(const float* rgb, std::size_t count, const cv::Mat& exemplar, int bins) {
  return colorHistogramDistance(rgb, count, exemplar.ptr<float>(), exemplar.total(), bins);
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
  checkOptions(exemplarImage, referenceImage, o);
  if (solid.color.empty() || solid.color.size() != solid.dims.count())
    throw InputError("the solid has no color grid covering its box");
  const cv::Mat exemplar = exemplarImage.clone(), reference = referenceImage.clone();  // continuous
  const SrgbVolume volume = srgbVolumeOf(solid);
  std::vector<PatchSource> sources{sliceSource(volume, false, o.planeAxis), sliceSource(volume, true, -1)};
  if (!reference.empty()) sources.push_back(imageSource(reference));
  const std::vector<PatchSimilarity> similarity = comparePatchSources(sources, exemplar, o);
  ContinuousQuality q;
  q.axis = similarity[0];
  q.oblique = similarity[1];
  q.colorHistogramDistance = colorDistance(volume.rgb.data(), volume.dims.count(), exemplar, o.histogramBins);
  if (!reference.empty()) {
    q.reference = similarity[2];
    q.referenceColorHistogramDistance =
        colorDistance(reference.ptr<float>(), reference.total(), exemplar, o.histogramBins);
  }
  q.positions = positionsOf(solid, exemplar.size());
  q.seconds = secondsSince(start);
  return q;
}

TextureQuality measureTexture(const cv::Mat& textureImage, const cv::Mat& exemplarImage,
                              const cv::Mat& referenceImage, const ContinuousQualityOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  checkOptions(exemplarImage, referenceImage, o);
  if (textureImage.empty() || textureImage.type() != CV_32FC3)
    throw InputError("the texture must be a 3-channel float sRGB image");
  const cv::Mat texture = textureImage.clone(), exemplar = exemplarImage.clone(),
                reference = referenceImage.clone();
  std::vector<PatchSource> sources{imageSource(texture)};
  if (!reference.empty()) sources.push_back(imageSource(reference));
  const std::vector<PatchSimilarity> similarity = comparePatchSources(sources, exemplar, o);
  TextureQuality q;
  q.texture = similarity[0];
  q.colorHistogramDistance = colorDistance(texture.ptr<float>(), texture.total(), exemplar, o.histogramBins);
  if (!reference.empty()) {
    q.reference = similarity[1];
    q.referenceColorHistogramDistance =
        colorDistance(reference.ptr<float>(), reference.total(), exemplar, o.histogramBins);
  }
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
