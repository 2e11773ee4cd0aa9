#include "particles/ParticleFactory.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>

#include <tbb/parallel_for.h>
#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "common/interruption.h"
#include "particles/rotation.h"
#include "particles/visualHull.h"
#include "particles/voxelizeHull.h"
#include "segmentation/particlePhases.h"

namespace solidtex {
namespace {

constexpr int kAttemptsPerHull = 32;
// A hull this small (share of its local cube) comes from contours that barely overlap: draw again.
constexpr double kMinHullVolume = 0.01;

void checkRange(const char* name, int value, int lo, int hi) {
  if (value < lo || value > hi)
    throw InputError(std::string("particle option ") + name + " must be in [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "], got " + std::to_string(value));
}

void checkOptions(const ParticleOptions& options) {
  checkRange("views", options.views, 1, 16);
  checkRange("shapes", options.shapes, 1, 100000);
  checkRange("contourVertices", options.contourVertices, 3, 10000);
  checkRange("smoothing resolution", options.smoothing.resolution, 8,
             64);  // its padded grid grows as its cube
  if (!(options.smoothing.radius >= 0 && options.smoothing.radius <= 0.5))
    throw InputError("particle smoothing must be in [0, 0.5], got " +
                     std::to_string(options.smoothing.radius));
  if (!(options.bodyForm >= -1 && options.bodyForm <= 1))
    throw InputError("particle body form must be in [-1, 1], got " + std::to_string(options.bodyForm));
}

// Particles whose contours carve the hulls; those cut by the photo's border only when there is no other.
std::vector<int> contourSources(const ExemplarStats& stats) {
  std::vector<int> inner, all;
  for (int i = 0; i < int(stats.particles.size()); ++i) {
    const Particle2D& p = stats.particles[std::size_t(i)];
    if (p.contour.size() < 3) continue;
    const cv::Rect box = cv::boundingRect(p.contour);
    if (box.width < 2 || box.height < 2) continue;
    all.push_back(i);
    if (!p.border) inner.push_back(i);
  }
  if (all.empty())
    throw InputError("no particle contour of " +
                     (stats.name.empty() ? std::string("the photo") : stats.name) +
                     " encloses an area: cannot build particle shapes");
  return inner.empty() ? all : inner;
}

std::optional<HullMesh> tryHull(const ExemplarStats& stats, const std::vector<int>& sources,
                                const ParticleOptions& options, Rng& rng) {
  std::vector<Silhouette> views(std::size_t(options.views));
  for (Silhouette& view : views) {
    const int source = sources[uniformIndex(rng, sources.size())];
    view.polygon = normalizeContour(stats.particles[std::size_t(source)].contour, options.contourVertices);
    view.rotation = randomRotation(rng);
  }
  HullMesh hull = visualHull(views);
  if (hull.volume() < kMinHullVolume) return std::nullopt;
  return hull;
}

// One plane's photo for aligned hulls: its statistics, the particles whose contours carve, and the
// view that maps its image onto the volume's axes. Columns: the image's x, its y (up, as
// normalizeContour flips the photo's rows), the viewing direction (their cross product).
struct PlaneView {
  const ExemplarStats* stats = nullptr;
  std::vector<int> sources;
  Eigen::Matrix3d rotation;
};

std::vector<PlaneView> planeViews(const ExemplarStats& xy, const PlanePhotos& planes) {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  const auto view = [](const ExemplarStats& stats, const Eigen::Vector3d& across,
                       const Eigen::Vector3d& down) {
    PlaneView v{&stats, contourSources(stats), {}};
    v.rotation << across, -down, across.cross(-down);
    return v;
  };
  return {view(xy, x, y), view(*planes.xz, x, z), view(*planes.yz, y, z)};
}

std::optional<HullMesh> tryAlignedHull(const std::vector<PlaneView>& planes, const ParticleOptions& options,
                                       Rng& rng) {
  std::vector<Silhouette> views;
  for (const PlaneView& plane : planes) {
    const int source = plane.sources[uniformIndex(rng, plane.sources.size())];
    views.push_back(
        {normalizeContour(plane.stats->particles[std::size_t(source)].contour, options.contourVertices),
         plane.rotation});
  }
  HullMesh hull = visualHull(views);
  if (hull.volume() < kMinHullVolume) return std::nullopt;
  return hull;
}

HullMesh buildHull(const ExemplarStats& stats, const std::vector<int>& sources,
                   const std::vector<PlaneView>& planes, const ParticleOptions& options, int index) {
  Rng rng(deriveSeed(options.seed, std::uint64_t(index)));
  checkInterruption();
  for (int attempt = 0; attempt < kAttemptsPerHull; ++attempt)
    if (std::optional<HullMesh> hull =
            planes.empty() ? tryHull(stats, sources, options, rng) : tryAlignedHull(planes, options, rng))
      return std::move(*hull);
  throw InputError("the photo's particle contours do not overlap enough to carve 3D particle shapes");
}

// Values with weights; drawWeighted picks one with probability proportional to its weight.
using Weighted = std::vector<std::pair<int, long>>;

int drawWeighted(const Weighted& candidates, Rng& rng) {
  long total = 0;
  for (const auto& [value, weight] : candidates) total += weight;
  auto draw = long(uniformIndex(rng, std::uint64_t(total)));
  for (const auto& [value, weight] : candidates) {
    if (draw < weight) return value;
    draw -= weight;
  }
  return candidates.back().first;
}

// The paper's second level (3.5): every pair sharing a value with (width, height), in either slot,
// offers its other value. A pair sharing both values offers each with half its count, so weights are
// doubled counts.
Weighted depthCandidates(const std::vector<SizePair>& pairs, int width, int height) {
  Weighted out;
  for (const SizePair& p : pairs) {
    const bool sharesWidth = p.width == width || p.width == height;
    const bool sharesHeight = p.height == width || p.height == height;
    if (sharesWidth && sharesHeight) {
      out.emplace_back(p.width, p.count);
      out.emplace_back(p.height, p.count);
    } else if (sharesWidth) {
      out.emplace_back(p.height, 2L * p.count);
    } else if (sharesHeight) {
      out.emplace_back(p.width, 2L * p.count);
    }
  }
  return out;
}

// A (width, height) that no photo pair shares a value with takes a side of any pair, by frequency.
Weighted anySide(const std::vector<SizePair>& pairs) {
  Weighted out;
  for (const SizePair& p : pairs) {
    out.emplace_back(p.width, p.count);
    out.emplace_back(p.height, p.count);
  }
  return out;
}

// Aligned: the z extents of the xz photo's boxes x wide and of the yz photo's y wide, by frequency.
int drawAlignedDepth(const PlanePhotos& planes, int x, int y, Rng& rng) {
  Weighted sharing, any;
  for (const auto& [photo, across] : {std::pair{planes.xz, x}, std::pair{planes.yz, y}})
    for (const SizePair& p : photo->sizePairs) {
      any.emplace_back(p.height, p.count);
      if (p.width == across) sharing.emplace_back(p.height, p.count);
    }
  if (!sharing.empty()) return drawWeighted(sharing, rng);
  if (!any.empty()) return drawWeighted(any, rng);
  return (x + y + 1) / 2;
}

// The sections of oblate bodies are as often narrow as wide, so the depth drawn from boxes sharing
// a side makes their bodies triaxial; the form puts back the two long sides that discs have (or
// the one that rods have).
ParticleSize formedBox(ParticleSize size, double form) {
  if (form == 0) return size;
  std::array<int*, 3> sides{&size.width, &size.height, &size.depth};
  std::sort(sides.begin(), sides.end(), [](const int* a, const int* b) { return *a < *b; });
  const int gap = form > 0 ? *sides[2] - *sides[1] : *sides[1] - *sides[0];
  *sides[1] += int(std::lround(form * gap));
  return size;
}

int drawDepth(const std::vector<SizePair>& pairs, int width, int height, Rng& rng) {
  Weighted candidates = depthCandidates(pairs, width, height);
  if (candidates.empty()) candidates = anySide(pairs);
  if (candidates.empty()) return (width + height + 1) / 2;
  return drawWeighted(candidates, rng);
}

// A non-border particle (any particle when all touch the border) whose box is nearest to
// (width, height) in |dw| + |dh|, which is 0 for the photo's own pairs; random among equals; of
// `phase` alone when it is not negative.
int drawSource(const std::vector<Particle2D>& particles, int width, int height, Rng& rng, int phase = -1) {
  const auto candidate = [phase](const Particle2D& p) { return phase < 0 || p.phase == phase; };
  const bool anyInner = std::any_of(particles.begin(), particles.end(),
                                    [&](const Particle2D& p) { return !p.border && candidate(p); });
  int best = INT_MAX;
  std::vector<int> ties;
  for (int i = 0; i < int(particles.size()); ++i) {
    const Particle2D& p = particles[std::size_t(i)];
    if (!candidate(p) || (anyInner && p.border)) continue;
    const int distance = std::abs(p.box.width - width) + std::abs(p.box.height - height);
    if (distance < best) ties.clear();
    if (distance <= best) {
      best = distance;
      ties.push_back(i);
    }
  }
  return ties.empty() ? -1 : ties[uniformIndex(rng, ties.size())];
}

// Each phase's contour sources (contourSources' rule within the phase; all phases' when it has
// none of its own); one list when the photo has one phase.
std::vector<std::vector<int>> phaseSources(const ExemplarStats& stats) {
  const std::vector<int> all = contourSources(stats);
  const int phases = std::max(1, stats.phaseCentres.rows);
  if (phases == 1) return {all};
  std::vector<std::vector<int>> out(static_cast<std::size_t>(phases));
  for (int p = 0; p < phases; ++p) {
    std::vector<Particle2D> own;
    std::vector<int> index;
    for (int i = 0; i < int(stats.particles.size()); ++i)
      if (stats.particles[std::size_t(i)].phase == p)
        own.push_back(stats.particles[std::size_t(i)]), index.push_back(i);
    ExemplarStats phase;
    phase.particles = std::move(own);
    try {
      for (int i : contourSources(phase)) out[std::size_t(p)].push_back(index[std::size_t(i)]);
    } catch (const InputError&) {
      out[std::size_t(p)] = all;
    }
  }
  return out;
}

// Each phase's (width, height) pairs; one list when the photo has one phase.
std::vector<std::vector<SizePair>> phaseSizePairs(const ExemplarStats& stats) {
  const int phases = std::max(1, stats.phaseCentres.rows);
  if (phases == 1) return {stats.sizePairs};
  std::vector<std::vector<SizePair>> out(static_cast<std::size_t>(phases));
  for (int p = 0; p < phases; ++p) out[std::size_t(p)] = phaseStats(stats, p).sizePairs;
  return out;
}

}  // namespace

ParticleFactory::ParticleFactory(const ExemplarStats& stats, const ParticleOptions& options,
                                 PlanePhotos planes)
    : stats_(stats), planes_(planes), options_(options) {
  checkOptions(options);
  const std::vector<std::vector<int>> sources = phaseSources(stats);
  const std::vector<PlaneView> views =
      planes.aligned() ? planeViews(stats, planes) : std::vector<PlaneView>{};
  sharpHulls_.resize(std::size_t(options.shapes));
  hulls_.resize(sharpHulls_.size());
  phasePairs_ = phaseSizePairs(stats);
  tbb::parallel_for(0, options.shapes, [&](int i) {
    sharpHulls_[std::size_t(i)] =
        buildHull(stats, sources[std::size_t(i) % sources.size()], views, options, i);
    hulls_[std::size_t(i)] = smoothHull(sharpHulls_[std::size_t(i)], options.smoothing);
  });
}

ParticleFactory::ParticleFactory(const ExemplarStats& stats, const ParticleOptions& options,
                                 PlanePhotos planes, std::vector<HullMesh> sharpHulls)
    : stats_(stats),
      planes_(planes),
      options_(options),
      sharpHulls_(std::move(sharpHulls)),
      hulls_(sharpHulls_.size()),
      phasePairs_(phaseSizePairs(stats)) {
  checkOptions(options);
  tbb::parallel_for(std::size_t(0), hulls_.size(),
                    [&](std::size_t i) { hulls_[i] = smoothHull(sharpHulls_[i], options.smoothing); });
}

ParticleFactory ParticleFactory::withSmoothing(const HullSmoothing& smoothing, int maxHulls) const {
  ParticleOptions options = options_;
  options.smoothing = smoothing;
  const std::size_t count =
      maxHulls > 0 ? std::min(sharpHulls_.size(), std::size_t(maxHulls)) : sharpHulls_.size();
  options.shapes = int(count);
  ParticleFactory out(stats_, options, planes_,
                      {sharpHulls_.begin(), sharpHulls_.begin() + std::ptrdiff_t(count)});
  out.phaseScales_ = phaseScales_;
  return out;
}

ParticleSize ParticleFactory::pickDepth(int width, int height, Rng& rng, int phase) const {
  if (phasePairs_.size() > 1) {
    // The source first: its phase's particles, not the other phases', tell the depth.
    const int source = drawSource(stats_.particles, width, height, rng, phase);
    return formedBox(
        {width, height, drawDepth(phasePairs_[std::size_t(phaseOf(source))], width, height, rng), source},
        options_.bodyForm);
  }
  if (aligned())
    return {width, height, drawAlignedDepth(planes_, width, height, rng),
            drawSource(stats_.particles, width, height, rng)};
  const int depth = drawDepth(stats_.sizePairs, width, height, rng);
  return formedBox({width, height, depth, drawSource(stats_.particles, width, height, rng)},
                   options_.bodyForm);
}

ParticleFactory ParticleFactory::withBodyForm(double form) const {
  ParticleOptions options = options_;
  options.bodyForm = form;
  checkOptions(options);
  ParticleFactory out = *this;
  out.options_ = options;
  return out;
}

void ParticleFactory::setPhaseScales(std::vector<double> scales) {
  if (scales.size() != phasePairs_.size() ||
      std::any_of(scales.begin(), scales.end(), [](double s) { return !(s > 0) || !std::isfinite(s); }))
    throw std::invalid_argument("setPhaseScales: one positive scale per phase");
  phaseScales_ = std::move(scales);
}

double ParticleFactory::phaseScale(int phase) const {
  return phaseScales_.empty() ? 1.0 : phaseScales_[std::size_t(phase)];
}

double ParticleFactory::largestPhaseScale() const {
  return phaseScales_.empty() ? 1.0 : *std::max_element(phaseScales_.begin(), phaseScales_.end());
}

int ParticleFactory::phaseOf(int source) const {
  return source < 0 ? 0 : stats_.particles[std::size_t(source)].phase;
}

VoxelShape ParticleFactory::make(int width, int height, int depth, Rng& rng, int phase) const {
  checkInterruption();
  // Hull i was carved from phase i mod K's contours.
  const std::size_t phases = phasePairs_.size(), p = std::size_t(phase);
  const std::size_t ofPhase = hulls_.size() > p ? (hulls_.size() - p + phases - 1) / phases : 0;
  const std::size_t hull =
      ofPhase > 0 ? p + phases * uniformIndex(rng, ofPhase) : uniformIndex(rng, hulls_.size());
  const Eigen::Matrix3d turn = aligned() ? Eigen::Matrix3d::Identity() : randomRotation(rng);
  VoxelShape shape = voxelize(hulls_[hull], turn, width, height, depth);
  shape.pose.hull = int(hull);
  return shape;
}

}  // namespace solidtex
