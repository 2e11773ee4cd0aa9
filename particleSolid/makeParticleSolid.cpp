#include "particleSolid/makeParticleSolid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <utility>

#include <tbb/parallel_for.h>

#include "common/Error.h"
#include "common/Random.h"
#include "common/memoryBudget.h"
#include "mesh/particleMeshes.h"
#include "placement/PlacementTimeline.h"
#include "placement/cropToCountedBox.h"
#include "placement/phaseShares.h"
#include "voxel/ParticleColoring.h"

namespace solidtex {
namespace {

constexpr int kSizingBootstraps = 50;  // enough for a 5-95 % band of the volume CDF

constexpr int kMatrixBlock = 64;     // largest edge of the synthesised matrix block, tiled over the volume
constexpr int kMinMatrixBlock = 16;  // below it the synthesis has no room for its levels

void report(const Progress& progress, const std::string& step, double fraction = -1) {
  if (progress) progress(step, fraction);
}

double voxelsPerPixel(const ParticleSolidOptions& options, int largestSide) {
  if (options.voxelsPerPixel <= 0) return defaultVoxelsPerPixel(largestSide, options.dims);
  // Below a voxel across, the photo's largest particle would be no particle at all.
  const double largest = largestSide;
  if (largest * options.voxelsPerPixel < 1) {
    char text[160];
    std::snprintf(
        text, sizeof text,
        "--scale %g makes the photo's largest particle (%g pixels across) less than a voxel: give at "
        "least %.3g",
        options.voxelsPerPixel, largest, 1 / largest);
    throw OptionError(text);
  }
  return options.voxelsPerPixel;
}

// The block's edge: a multiple of 4 (the synthesis' levels), no larger than the volume needs, and
// in a periodic volume a divisor of every side, so that the tiling wraps with the volume. 0: none.
int matrixBlock(const Dims& dims, bool periodic) {
  if (!periodic) return std::min(kMatrixBlock, (std::max({dims.x, dims.y, dims.z}) + 3) / 4 * 4);
  const int common = std::gcd(dims.x, std::gcd(dims.y, dims.z));
  for (int block = kMatrixBlock; block >= kMinMatrixBlock; block -= 4)
    if (common % block == 0) return block;
  return 0;
}

using BlockSynthesis = std::optional<TiledMatrix> (*)(const ExemplarStats&, const MatrixSynthesisOptions&);

// A synthesised block of one of the solid's textures (the matrix, the particles' grain), or none
// (projection) with the reason in `choice`.
std::optional<TiledMatrix> makeBlock(const ParticleSolidOptions& options, Texture texture,
                                     BlockSynthesis synthesize, const ExemplarStats& stats, double scale,
                                     std::uint64_t stream, const char* tooLittle, const Progress& progress,
                                     const char* step, TextureChoice& choice) {
  choice = {texture, 0, {}};
  if (texture == Texture::Projected) return std::nullopt;
  report(progress, step);
  const int block = matrixBlock(options.dims, options.boundary == Boundary::Periodic);
  if (block < kMinMatrixBlock) {
    choice = {Texture::Projected, 0, "no block of 16 to 64 voxels, a multiple of 4, tiles this volume"};
    return std::nullopt;
  }
  std::optional<TiledMatrix> result = synthesize(stats, {block, scale, deriveSeed(options.seed, stream), 0});
  if (!result)
    choice = {Texture::Projected, 0, tooLittle};
  else
    choice.block = block;
  return result;
}

// The photo's visual hulls, formed and rounded as asked, or as far as makes their sections look like
// the photo's particles at the sizes the solid will have (formed first, then sized with the sharp
// hulls).
ParticleFactory makeFactory(const ParticleSolidOptions& options, const ExemplarStats& stats,
                            PlanePhotos planes, double scale, BodyFormFit& form, SmoothingFit& smoothing) {
  ParticleOptions particles = options.particles;
  particles.seed = options.seed;
  particles.smoothing.radius = options.smoothing.value_or(0);
  particles.bodyForm = 0;
  const ParticleFactory hulls(stats, particles, planes);
  if (options.bodyForm)
    form.form = *options.bodyForm;
  else
    form = fitBodyForm(stats, hulls, scale, options.seed);
  ParticleFactory factory = hulls.withBodyForm(form.form);
  if (options.smoothing) {
    smoothing.radius = *options.smoothing;
    return factory;
  }
  const double sizeFactor = options.sizing == Sizing::Sections
                                ? fitSectionSizing(stats, factory, scale, options.seed).sizeFactor
                                : 1.0;
  smoothing = fitHullSmoothing(stats, factory, scale, sizeFactor, options.seed);
  particles.smoothing.radius = smoothing.radius;
  return factory.withSmoothing(particles.smoothing);
}

// Each mesh takes its particle's mean colour, texture and all. The sums go by a fixed set of
// slabs, added in order, so the colours do not depend on the thread count.
void paintMeshes(std::vector<ParticleMesh>& meshes, const SolidVolume& volume) {
  using Sums = std::vector<std::array<double, 4>>;  // per id: r, g, b, count
  const Dims& d = volume.dims;
  constexpr int kSlabs = 16;
  std::vector<Sums> slabs(kSlabs, Sums(meshes.size() + 1, {0, 0, 0, 0}));
  tbb::parallel_for(0, kSlabs, [&](int slab) {
    for (int z = slab * d.z / kSlabs; z < (slab + 1) * d.z / kSlabs; ++z)
      for (int y = 0; y < d.y; ++y)
        for (int x = 0; x < d.x; ++x) {
          const std::int32_t id = volume.particleId[d.index(x, y, z)];
          if (id == 0) continue;
          auto& sum = slabs[std::size_t(slab)][std::size_t(id)];
          const Rgb rgb = volume.colorAt(x, y, z);
          for (int c = 0; c < 3; ++c) sum[std::size_t(c)] += rgb[std::size_t(c)];
          sum[3] += 1;
        }
  });
  for (ParticleMesh& m : meshes) {
    std::array<double, 4> sum{0, 0, 0, 0};
    for (const Sums& slab : slabs)
      for (int c = 0; c < 4; ++c) sum[std::size_t(c)] += slab[std::size_t(m.id)][std::size_t(c)];
    for (int c = 0; c < 3; ++c) m.color[std::size_t(c)] = float(sum[std::size_t(c)] / std::max(1.0, sum[3]));
  }
}

}  // namespace

Boundary parseBoundary(const std::string& name) {
  if (name == "open") return Boundary::Open;
  if (name == "walls") return Boundary::Walls;
  if (name == "periodic") return Boundary::Periodic;
  throw OptionError("unknown boundary '" + name + "': use open, walls or periodic");
}

const char* boundaryName(Boundary boundary) {
  switch (boundary) {
    case Boundary::Open:
      return "open";
    case Boundary::Walls:
      return "walls";
    case Boundary::Periodic:
      return "periodic";
  }
  return "unknown";
}

Texture parseTexture(const std::string& option, const std::string& name) {
  if (name == "synthesized") return Texture::Synthesized;
  if (name == "projected") return Texture::Projected;
  throw OptionError(option + ": unknown texture '" + name + "': use synthesized or projected");
}

const char* textureName(Texture texture) {
  return texture == Texture::Synthesized ? "synthesized" : "projected";
}

int largestBoxSide(const ExemplarStats& stats) {
  int side = 1;
  for (const auto& pair : stats.sizePairs) side = std::max({side, pair.width, pair.height});
  return side;
}

double defaultVoxelsPerPixel(int largestSide, const Dims& dims) {
  // 1:1 keeps particle shapes as resolved as in the photo, unless particles would be so large
  // that few fit and the walls dominate the packing.
  const int smallestEdge = std::min({dims.x, dims.y, dims.z});
  return std::min(1.0, 0.25 * smallestEdge / largestSide);
}

float placementRadiusCap(int largestSide, double voxelsPerPixel) {
  return float(std::sqrt(3.0) * std::ceil(largestSide * voxelsPerPixel) / 2 + 1);
}

int openBoundaryMargin(int largestSide, double particleScale) {
  return int(std::ceil(largestSide * particleScale / 2));
}

double targetVolumeFraction(const ParticleSolid& solid) {
  double sum = solid.stats.areaFraction;
  for (const ExemplarStats& plane : solid.planeStats) sum += plane.areaFraction;
  return sum / double(solid.planeStats.size() + 1);
}

void checkParticleSolidOptions(const ParticleSolidOptions& options) {
  for (int edge : {options.dims.x, options.dims.y, options.dims.z})
    if (edge < 8 || edge > kMaxVolumeEdge)
      throw OptionError("volume size " + std::to_string(edge) + " is out of range [8, " +
                        std::to_string(kMaxVolumeEdge) + "]");
  if (options.voxelsPerPixel < 0 || options.voxelsPerPixel > 64)
    throw OptionError("--scale must be in (0, 64] voxels per pixel");
  if (options.particles.views < 3 || options.particles.views > 5)
    throw OptionError("--views must be 3, 4 or 5");
  if (options.particles.shapes < 1 || options.particles.shapes > 4096)
    throw OptionError("--shapes must be in [1, 4096]");
  if (options.brickEdge < 0)
    throw OptionError("--bricks must be positive, got " + std::to_string(options.brickEdge));
}

double particleSolidPeakBytes(const Dims& dims, const Dims& placed, PlacerKind placer, bool denseColor) {
  constexpr double kEveryRun = 200.0 * 1024 * 1024;
  constexpr double kPerPlacedVoxel = 7.6, kIdBytes = 4;
  // Dense: 16.3 measured for the .vdb written from dense colours (f03a6e6), 3 more for a TIFF's copy.
  const double perVoxelWriting = denseColor ? 19.3 : 8.2;
  // delaunay's triangulation of the free space: 1459 MiB against edt's 673 for gravel at 256^3, walls.
  constexpr double kDelaunayPerPlacedVoxel = 49;
  const double voxels = double(dims.count()), placedVoxels = double(placed.count());
  const double perPlacedVoxel =
      kPerPlacedVoxel + (placer == PlacerKind::Delaunay ? kDelaunayPerPlacedVoxel : 0);
  return kEveryRun + std::max(perPlacedVoxel * placedVoxels + kIdBytes * voxels, perVoxelWriting * voxels);
}

ParticleSolidBuilder::ParticleSolidBuilder(ParticleSolidOptions options, Progress progress)
    : options_(std::move(options)), progress_(std::move(progress)) {
  checkParticleSolidOptions(options_);
  // The margin is not known before the photo is: at least this much.
  requireVolumeBytes(
      "the volume", options_.dims,
      particleSolidPeakBytes(options_.dims, options_.dims, options_.placer, options_.denseColor));
}

const ExemplarStats& ParticleSolidBuilder::analyze(const cv::Mat& photoSrgb, const std::string& name) {
  solid_.timer.start("analysis");
  report(progress_, "segmenting the photo");
  solid_.stats = analyzeExemplar(photoSrgb, name, options_.segmentation);
  if (options_.phases.any()) report(progress_, "sorting the particles into phases");
  if (std::optional<ParticlePhases> phases = findPhases(solid_.stats, options_.phases, options_.seed)) {
    assignPhases(solid_.stats, *phases);
    solid_.phases = std::move(*phases);
  }
  photo_ = photoSrgb;
  return solid_.stats;
}

void ParticleSolidBuilder::analyzePlanes(const cv::Mat& xzSrgb, const std::string& xzName,
                                         const cv::Mat& yzSrgb, const std::string& yzName) {
  const auto isTheXyPhoto = [&](const cv::Mat& photo) {
    return photo.size() == photo_.size() && photo.type() == photo_.type() &&
           cv::norm(photo, photo_, cv::NORM_INF) == 0;
  };
  if (factory_) throw std::logic_error("analyzePlanes after makeParticles");
  if (isTheXyPhoto(xzSrgb) && isTheXyPhoto(yzSrgb)) return;
  if (options_.segmentation.maskPath || !options_.segmentation.mask.empty())
    throw OptionError("--mask segments one photo: give it without --photo-xz and --photo-yz");
  if (options_.phases.any())
    throw OptionError(
        "--phases and --phase-mask sort one photo's particles: give them without --photo-xz "
        "and --photo-yz");
  if (options_.bodyForm && *options_.bodyForm != 0)
    throw OptionError("--body-form forms one photo's particles; three photos' keep their aligned boxes");
  report(progress_, "segmenting the xz and yz photos");
  const ExemplarStats xz = analyzeExemplar(xzSrgb, xzName, options_.segmentation);
  const bool oneForBoth = xzSrgb.data == yzSrgb.data && xzSrgb.size() == yzSrgb.size();
  solid_.planeStats = {xz, oneForBoth ? xz : analyzeExemplar(yzSrgb, yzName, options_.segmentation)};
}

int ParticleSolidBuilder::largestSide() const {
  int side = largestBoxSide(solid_.stats);
  for (const ExemplarStats& plane : solid_.planeStats) side = std::max(side, largestBoxSide(plane));
  return side;
}

void ParticleSolidBuilder::makeParticles() {
  const ExemplarStats& stats = solid_.stats;
  const double scale = solid_.voxelsPerPixel = voxelsPerPixel(options_, largestSide());
  solid_.timer.start("particle_shapes");
  report(progress_, "building particle shapes");
  const PlanePhotos planes = solid_.planeStats.size() == 2
                                 ? PlanePhotos{&solid_.planeStats[0], &solid_.planeStats[1]}
                                 : PlanePhotos{};
  factory_.emplace(makeFactory(options_, stats, planes, scale, solid_.bodyForm, solid_.smoothing));

  solid_.timer.start("sizing");
  solid_.sizing = {1, {}, stats.histogram.ratios, 0, {}};
  if (options_.sizing == Sizing::Sections) {
    report(progress_, "sizing particles from their sections");
    if (stats.phaseCentres.rows > 1) return sizePhases(scale);
    solid_.sizing = fitSectionSizing(stats, *factory_, scale, options_.seed, kSizingBootstraps);
  }
  solid_.sizing.particleWeights =
      phaseBalancedWeights(stats, *factory_, std::move(solid_.sizing.particleWeights),
                           scale * solid_.sizing.sizeFactor, options_.seed);
}

// Each phase's sections unfold on their own: unfolded together, a phase of large particles takes
// the small sections of another for its own cuts, and both phases' sizes and shares go wrong.
void ParticleSolidBuilder::sizePhases(double scale) {
  const ExemplarStats& stats = solid_.stats;
  std::vector<double> weights(stats.particles.size(), 0.0);
  std::vector<double>& factors = solid_.phaseSizeFactors;
  factors.assign(std::size_t(stats.phaseCentres.rows), 1.0);
  double worstKs = 0;
  for (int k = 0; k < stats.phaseCentres.rows; ++k) {
    std::vector<std::size_t> members;
    for (std::size_t i = 0; i < stats.particles.size(); ++i)
      if (stats.particles[i].phase == k) members.push_back(i);
    const SectionSizing fit = fitSectionSizing(phaseStats(stats, k), *factory_, scale, options_.seed);
    factors[std::size_t(k)] = fit.sizeFactor;
    worstKs = std::max(worstKs, fit.predictedKs);
    for (std::size_t j = 0; j < members.size(); ++j) weights[members[j]] = fit.particleWeights[j];
  }
  factory_->setPhaseScales(factors);
  weights = phaseBalancedWeights(stats, *factory_, std::move(weights), scale, options_.seed);
  std::array<double, 10> binRatios{};
  double total = 0;
  for (std::size_t i : statisticalParticles(stats.particles)) {
    binRatios[std::size_t(stats.histogram.binOf(stats.particles[i].area))] += weights[i];
    total += weights[i];
  }
  for (double& ratio : binRatios) ratio = total > 0 ? ratio / total : 0;
  solid_.sizing = {1, std::move(weights), binRatios, worstKs, {}};
}

const PlacementResult& ParticleSolidBuilder::place() {
  const ExemplarStats& stats = solid_.stats;
  solid_.timer.start("placement");
  // Particles sizeFactor times the photo's boxes (the largest phase's factor with several): that
  // many more voxels per photo pixel for them.
  const double particleScale =
      solid_.voxelsPerPixel * solid_.sizing.sizeFactor * factory_->largestPhaseScale();
  const Dims& dims = options_.dims;
  const int margin =
      options_.boundary == Boundary::Open ? openBoundaryMargin(largestSide(), particleScale) : 0;
  const Dims placed{dims.x + 2 * margin, dims.y + 2 * margin, dims.z + 2 * margin};
  solid_.memoryEstimate = particleSolidPeakBytes(dims, placed, options_.placer, options_.denseColor);
  requireVolumeBytes(margin > 0 ? "placing particles in a block" : "placing particles", placed,
                     solid_.memoryEstimate);
  const bool periodic = options_.boundary == Boundary::Periodic;
  const float radiusCap = placementRadiusCap(largestSide(), particleScale);
  PlacementOptions placement;
  placement.dims = placed;
  placement.periodic = periodic;
  if (margin > 0) placement.counted = Box::at({margin, margin, margin}, dims);
  placement.voxelsPerPixel = solid_.voxelsPerPixel;
  if (!solid_.planeStats.empty()) placement.volumeFraction = targetVolumeFraction(solid_);
  placement.seed = options_.seed;
  placement.arrangement = options_.arrangement;
  if (!solid_.sizing.particleWeights.empty()) {
    placement.particleWeights = solid_.sizing.particleWeights;
    placement.sizeFactor = solid_.sizing.sizeFactor;
  }
  std::optional<PlacementTimeline> timeline;
  const double largest = largestSide() * particleScale;
  // Bricks report after each brick: their progress needs no timing.
  if (const std::optional<Dims> block = options_.timePlacement && options_.brickEdge == 0
                                            ? timelineBlock(placed, dims, largest)
                                            : std::nullopt) {
    solid_.timer.start("placement_timing");
    report(progress_, "timing the placement on a smaller block");
    timeline = timePlacement(stats, *factory_, options_.placer, radiusCap, placement, *block);
    returnFreedMemory();
    solid_.timer.start("placement");
  }
  const double target = targetFraction(stats, placement);
  placement.progress = [&](double fraction, int count) {
    char line[128];
    std::snprintf(line, sizeof line, "placing particles: %d placed, volume fraction %.3f of %.3f", count,
                  fraction, target);
    report(progress_, line, timeline && target > 0 ? timeline->timeShare(fraction / target) : -1);
  };
  if (options_.brickEdge > 0) {
    solid_.bricks = placeInBricks(
        stats, *factory_, {placement, options_.placer, radiusCap, options_.brickEdge, options_.brickTeam});
    solid_.placement = std::move(solid_.bricks->placement);
  } else {
    auto field = makeSpaciousnessField(options_.placer, placed, radiusCap, periodic);
    solid_.placement = placeLargestFirst(stats, *factory_, *field, placement);
    field.reset();  // placement's largest part, given back before the solid is painted
  }
  returnFreedMemory();
  solid_.wholeVolumes = wholeParticleVolumes(solid_.placement);
  if (margin > 0) solid_.placement = cropToCountedBox(std::move(solid_.placement));
  return solid_.placement;
}

ParticleSolid ParticleSolidBuilder::finish() {
  const ExemplarStats& stats = solid_.stats;
  const double scale = solid_.voxelsPerPixel;
  PlacementResult& placement = solid_.placement;
  solid_.timer.start("matrix");
  std::optional<TiledMatrix> matrix =
      makeBlock(options_, options_.matrix, synthesizeMatrix, stats, scale, 0x3A7B1C,
                "the photo shows too little matrix to learn its texture", progress_,
                "synthesizing the matrix", solid_.matrix);
  solid_.timer.start("particle_grain");
  std::optional<TiledMatrix> grain =
      makeBlock(options_, options_.particleTexture, synthesizeParticleGrain, stats, scale, 0x6A17E5,
                "the photo shows too little of its particles to learn their grain", progress_,
                "synthesizing the particles' grain", solid_.particleTexture);

  solid_.timer.start("color");
  report(progress_, "painting the particles");
  std::vector<ParticlePaint> paints;
  paints.reserve(placement.particles.size());
  for (const PlacedParticle& placed : placement.particles)
    paints.push_back({placed.source,
                      {placed.origin.x + placed.box.x * 0.5, placed.origin.y + placed.box.y * 0.5,
                       placed.origin.z + placed.box.z * 0.5},
                      placed.voxelsPerPixel});
  // Painted when asked (writing paints the .vdb's colour leaf by leaf): never held dense here.
  solid_.volume.dims = placement.dims;
  solid_.volume.particleId = std::move(placement.ids);
  solid_.volume.coloring = std::make_shared<ParticleColoring>(
      stats, placement.dims, std::move(paints), scale, options_.seed, options_.boundary == Boundary::Periodic,
      std::move(matrix), std::move(grain));
  placement.ids.clear();
  if (stats.phaseCentres.rows > 1) {
    int largestId = 0;
    for (const PlacedParticle& placed : placement.particles) largestId = std::max(largestId, placed.id);
    solid_.volume.particlePhase.resize(std::size_t(largestId));
    for (const PlacedParticle& placed : placement.particles)
      solid_.volume.particlePhase[std::size_t(placed.id) - 1] =
          std::uint8_t(stats.particles[std::size_t(placed.source)].phase);
  }

  if (options_.meshes) {
    solid_.timer.start("meshes");
    report(progress_, "meshing the particles");
    solid_.meshes = particleMeshes(placement, factory_->hulls());
    paintMeshes(solid_.meshes, solid_.volume);
  }
  return std::move(solid_);
}

ParticleSolid makeParticleSolid(const cv::Mat& photoSrgb, const std::string& name,
                                const ParticleSolidOptions& options, const Progress& progress) {
  ParticleSolidBuilder builder(options, progress);
  builder.analyze(photoSrgb, name);
  builder.makeParticles();
  builder.place();
  return builder.finish();
}

}  // namespace solidtex
