#include "pipeline/particleSolidJob.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <numeric>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include "Version.h"

#include "common/Error.h"
#include "mesh/meshTopology.h"
#include "mesh/particleMeshes.h"
#include "mesh/writeParticleMeshes.h"
#include "particles/fitHullSmoothing.h"
#include "pipeline/jobSupport.h"
#include "placement/cropPlacement.h"
#include "placement/placeLargestFirst.h"
#include "segmentation/imageIO.h"
#include "segmentation/reportJson.h"
#include "synthesis/synthesizeMatrix.h"
#include "voxel/paintParticleSolid.h"
#include "voxel/vdbIO.h"
#include "voxel/writePreviews.h"

namespace solidtex {
namespace {

// Peak resident memory per voxel of the placement block: 691 MiB for gravel at 256^3 with walls.
constexpr double kPlacementBytesPerVoxel = 40;

void checkJob(const ParticleSolidJob& job) {
  for (int edge : {job.dims.x, job.dims.y, job.dims.z})
    if (edge < 8 || edge > kMaxVolumeEdge)
      throw OptionError("volume size " + std::to_string(edge) + " is out of range [8, " +
                        std::to_string(kMaxVolumeEdge) + "]");
  if (job.voxelsPerPixel < 0 || job.voxelsPerPixel > 64)
    throw OptionError("--scale must be in (0, 64] voxels per pixel");
  if (job.particles.views < 3 || job.particles.views > 5) throw OptionError("--views must be 3, 4 or 5");
  if (job.particles.shapes < 1 || job.particles.shapes > 4096)
    throw OptionError("--shapes must be in [1, 4096]");
}

std::map<std::string, std::string> metadataOf(const ParticleSolidJob& job, const ExemplarStats& stats,
                                              const PlacementResult& placement, double scale,
                                              const SectionSizing& sizing, double smoothing) {
  char fraction[32], voxelsPerPixel[32];
  std::snprintf(fraction, sizeof fraction, "%.6f", placement.volumeFraction);
  std::snprintf(voxelsPerPixel, sizeof voxelsPerPixel, "%.9g", scale);
  return {{"solidtex_version", SOLIDTEX_VERSION},
          {"command_line", job.commandLine},
          {"seed", std::to_string(job.seed)},
          {"exemplar", std::filesystem::path(stats.name).filename().string()},
          {"volume_fraction", fraction},
          {"voxels_per_pixel", voxelsPerPixel},
          {"placer", placerName(job.placer)},
          {"sizing", sizingName(job.sizing)},
          {"arrangement", arrangementName(job.arrangement)},
          {"boundary", boundaryName(job.boundary)},
          {"size_factor", std::to_string(sizing.sizeFactor)},
          {"smoothing", std::to_string(smoothing)}};
}

nlohmann::json placementJson(const PlacementResult& placement, const ExemplarStats& stats, double scale) {
  return {
      {"dims", {placement.dims.x, placement.dims.y, placement.dims.z}},
      {"voxels_per_pixel", scale},
      {"particles", placement.particles.size()},
      {"volume_fraction", placement.volumeFraction},
      {"area_fraction", stats.areaFraction},
      {"placed_per_bin", placement.placedPerBin},
      {"rejected_per_bin", placement.rejectedPerBin},
      {"area_histogram", stats.histogram.ratios},
      {"volume_histogram", placement.volumeHistogram},
      {"stop_reason", placement.stopReason},
      {"shrinking",
       {{"steps", placement.shrinkSteps},
        {"smallest_scale", placement.smallestScale},
        {"particles_shrunk", placement.particlesBeforeShrinking < 0
                                 ? 0
                                 : int(placement.particles.size()) - placement.particlesBeforeShrinking}}}};
}

// Each mesh takes its particle's mean colour, texture and all.
void paintMeshes(std::vector<ParticleMesh>& meshes, const SolidVolume& volume) {
  std::vector<std::array<double, 4>> sums(meshes.size() + 1, {0, 0, 0, 0});  // per id: r, g, b, count
  for (std::size_t i = 0; i < volume.particleId.size(); ++i) {
    auto& sum = sums[std::size_t(volume.particleId[i])];
    for (int c = 0; c < 3; ++c) sum[std::size_t(c)] += volume.color[i][std::size_t(c)];
    sum[3] += 1;
  }
  for (ParticleMesh& m : meshes) {
    const auto& sum = sums[std::size_t(m.id)];
    for (int c = 0; c < 3; ++c) m.color[std::size_t(c)] = float(sum[std::size_t(c)] / std::max(1.0, sum[3]));
  }
}

nlohmann::json meshReport(OutputFiles& outputs, const std::string& path,
                          const std::vector<ParticleMesh>& meshes) {
  std::size_t triangles = 0;
  for (const ParticleMesh& m : meshes) triangles += m.surface.triangles.size();
  const int closed = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, meshes.size()), 0,
      [&](const tbb::blocked_range<std::size_t>& range, int count) {
        for (std::size_t i = range.begin(); i < range.end(); ++i)
          count += meshTopology(meshes[i].surface).closed;
        return count;
      },
      std::plus<>());
  const std::vector<std::string> files = writeParticleMeshes(outputs, path, meshes);
  return {{"path", path},
          {"files", files.size()},
          {"particles", meshes.size()},
          {"triangles", triangles},
          {"closed_manifold", closed}};
}

}  // namespace

Boundary parseBoundary(const std::string& name) {
  if (name == "open") return Boundary::Open;
  if (name == "walls") return Boundary::Walls;
  if (name == "periodic") return Boundary::Periodic;
  throw OptionError("unknown boundary '" + name + "': use open, walls or periodic");
}

Texture parseTexture(const std::string& option, const std::string& name) {
  if (name == "synthesized") return Texture::Synthesized;
  if (name == "projected") return Texture::Projected;
  throw OptionError(option + ": unknown texture '" + name + "': use synthesized or projected");
}

const char* textureName(Texture texture) {
  return texture == Texture::Synthesized ? "synthesized" : "projected";
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

int openBoundaryMargin(const ExemplarStats& stats, double particleScale) {
  return int(std::ceil(largestBoxSide(stats) * particleScale / 2));
}

int largestBoxSide(const ExemplarStats& stats) {
  int side = 1;
  for (const auto& pair : stats.sizePairs) side = std::max({side, pair.width, pair.height});
  return side;
}

double voxelsPerPixel(const ParticleSolidJob& job, const ExemplarStats& stats) {
  if (job.voxelsPerPixel <= 0) return defaultVoxelsPerPixel(stats, job.dims);
  // Below a voxel across, the photo's largest particle would be no particle at all.
  const double largest = largestBoxSide(stats);
  if (largest * job.voxelsPerPixel < 1) {
    char text[160];
    std::snprintf(
        text, sizeof text,
        "--scale %g makes the photo's largest particle (%g pixels across) less than a voxel: give at "
        "least %.3g",
        job.voxelsPerPixel, largest, 1 / largest);
    throw OptionError(text);
  }
  return job.voxelsPerPixel;
}

double defaultVoxelsPerPixel(const ExemplarStats& stats, const Dims& dims) {
  // 1:1 keeps particle shapes as resolved as in the photo, unless particles would be so large
  // that few fit and the walls dominate the packing.
  const int smallestEdge = std::min({dims.x, dims.y, dims.z});
  return std::min(1.0, 0.25 * smallestEdge / largestBoxSide(stats));
}

float placementRadiusCap(const ExemplarStats& stats, double voxelsPerPixel) {
  return float(std::sqrt(3.0) * std::ceil(largestBoxSide(stats) * voxelsPerPixel) / 2 + 1);
}

constexpr int kMatrixBlock = 64;     // largest edge of the synthesised matrix block, tiled over the volume
constexpr int kMinMatrixBlock = 16;  // below it the synthesis has no room for its levels

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
// (projection) with the reason in the report.
std::optional<TiledMatrix> makeBlock(const ParticleSolidJob& job, Texture texture, BlockSynthesis synthesize,
                                     const ExemplarStats& stats, double scale, std::uint64_t stream,
                                     const char* tooLittle, ProgressLine& progress, const char* step,
                                     nlohmann::json& report) {
  report = {{"texture", textureName(texture)}};
  if (texture == Texture::Projected) return std::nullopt;
  progress.update(step);
  const int block = matrixBlock(job.dims, job.boundary == Boundary::Periodic);
  if (block < kMinMatrixBlock) {
    report = {{"texture", "projected"},
              {"reason", "no block of 16 to 64 voxels, a multiple of 4, tiles this volume"}};
    return std::nullopt;
  }
  std::optional<TiledMatrix> result = synthesize(stats, {block, scale, deriveSeed(job.seed, stream), 0});
  if (!result)
    report = {{"texture", "projected"}, {"reason", tooLittle}};
  else
    report["block"] = block;
  return result;
}

constexpr int kSizingBootstraps = 8;  // a range of the size factor, at a fraction of the fit's time

// The photo's visual hulls, rounded as asked, or as far as makes their sections look like the photo's
// particles at the sizes the solid will have (sized first with the sharp hulls).
ParticleFactory makeFactory(const ParticleSolidJob& job, const ExemplarStats& stats, double scale,
                            SmoothingFit& smoothing) {
  ParticleOptions options = job.particles;
  options.seed = job.seed;
  options.smoothing.radius = job.smoothing.value_or(0);
  ParticleFactory factory(stats, options);
  if (job.smoothing) {
    smoothing.radius = *job.smoothing;
    return factory;
  }
  const double sizeFactor =
      job.sizing == Sizing::Sections ? fitSectionSizing(stats, factory, scale, job.seed).sizeFactor : 1.0;
  smoothing = fitHullSmoothing(stats, factory, scale, sizeFactor, job.seed);
  options.smoothing.radius = smoothing.radius;
  return factory.withSmoothing(options.smoothing);
}

nlohmann::json runParticleSolid(const ParticleSolidJob& job) {
  checkJob(job);
  requireVolumeMemory("the volume", job.dims, kPlacementBytesPerVoxel);
  OutputFiles outputs;
  outputs.addInput(job.photo);
  if (job.segmentation.maskPath) outputs.addInput(*job.segmentation.maskPath);
  addVolumeOutputs(outputs, job.output, job.report, job.preview);
  addVolumeExports(outputs, job.exports);
  if (job.meshes) addParticleMeshes(outputs, "--meshes", *job.meshes);
  PhaseTimer timer;
  ProgressLine progress(job.progress);

  timer.start("analysis");
  progress.update("segmenting the photo");
  const cv::Mat photo = loadPhoto(job.photo);
  const ExemplarStats stats = analyzeExemplar(photo, job.photo, job.segmentation);
  warnOfDroppedRegions(stats, &progress);
  const double scale = voxelsPerPixel(job, stats);

  timer.start("particle_shapes");
  progress.update("building particle shapes");
  SmoothingFit smoothing;
  const ParticleFactory factory = makeFactory(job, stats, scale, smoothing);

  timer.start("sizing");
  SectionSizing sizing{1, {}, stats.histogram.ratios, 0, {}};
  if (job.sizing == Sizing::Sections) {
    progress.update("sizing particles from their sections");
    sizing = fitSectionSizing(stats, factory, scale, job.seed, kSizingBootstraps);
  }
  // Particles sizeFactor times the photo's boxes: that many more voxels per photo pixel for them.
  const double particleScale = scale * sizing.sizeFactor;

  timer.start("placement");
  const int margin = job.boundary == Boundary::Open ? openBoundaryMargin(stats, particleScale) : 0;
  const Dims placed{job.dims.x + 2 * margin, job.dims.y + 2 * margin, job.dims.z + 2 * margin};
  requireVolumeMemory(margin > 0 ? "placing particles in a block" : "placing particles", placed,
                      kPlacementBytesPerVoxel);
  const bool periodic = job.boundary == Boundary::Periodic;
  auto field = makeSpaciousnessField(job.placer, placed, placementRadiusCap(stats, particleScale), periodic);
  PlacementOptions placementOptions;
  placementOptions.dims = placed;
  placementOptions.periodic = periodic;
  if (margin > 0) placementOptions.counted = VolumeBox{{margin, margin, margin}, job.dims};
  placementOptions.voxelsPerPixel = scale;
  placementOptions.seed = job.seed;
  placementOptions.arrangement = job.arrangement;
  if (job.sizing == Sizing::Sections) {
    placementOptions.particleWeights = sizing.particleWeights;
    placementOptions.sizeFactor = sizing.sizeFactor;
  }
  placementOptions.progress = [&](double fraction, int count) {
    char line[128];
    std::snprintf(line, sizeof line, "placing particles: %d placed, volume fraction %.3f of %.3f", count,
                  fraction, stats.areaFraction);
    progress.update(line, stats.areaFraction > 0 ? fraction / stats.areaFraction : -1);
  };
  PlacementResult placement = placeLargestFirst(stats, factory, *field, placementOptions);
  if (margin > 0) placement = cropPlacement(placement, {margin, margin, margin}, job.dims);
  field.reset();  // its memory goes to the colour and the .vdb's grids
  progress.done();

  timer.start("matrix");
  nlohmann::json matrixReport;
  const std::optional<TiledMatrix> matrix =
      makeBlock(job, job.matrix, synthesizeMatrix, stats, scale, 0x3A7B1C,
                "the photo shows too little matrix to learn its texture", progress, "synthesizing the matrix",
                matrixReport);
  timer.start("particle_grain");
  nlohmann::json grainReport;
  const std::optional<TiledMatrix> grain =
      makeBlock(job, job.particleTexture, synthesizeParticleGrain, stats, scale, 0x6A17E5,
                "the photo shows too little of its particles to learn their grain", progress,
                "synthesizing the particles' grain", grainReport);

  timer.start("color");
  progress.update("painting the particles");
  std::vector<ParticlePaint> paints;
  paints.reserve(placement.particles.size());
  for (const PlacedParticle& placed : placement.particles)
    paints.push_back({placed.source,
                      {placed.origin.x + placed.box.x * 0.5, placed.origin.y + placed.box.y * 0.5,
                       placed.origin.z + placed.box.z * 0.5},
                      placed.voxelsPerPixel});
  SolidVolume volume =
      paintParticleSolid(stats, placement.dims, std::move(placement.ids), paints, scale, job.seed, periodic,
                         matrix ? &*matrix : nullptr, grain ? &*grain : nullptr);
  volume.metadata = metadataOf(job, stats, placement, scale, sizing, smoothing.radius);

  std::vector<ParticleMesh> meshes;
  if (job.meshes) {
    timer.start("meshes");
    progress.update("meshing the particles");
    meshes = particleMeshes(placement, factory.hulls());
    paintMeshes(meshes, volume);
  }

  timer.start("write");
  progress.update("writing the outputs");
  nlohmann::json written = {{"vdb", job.output}};
  if (job.meshes) written["meshes"] = meshReport(outputs, *job.meshes, meshes);
  if (job.preview) written["previews"] = writePreviews(outputs, *job.preview, photo, volume);
  // A voxel is 1 / scale of the photo's pixels, whose size in µm a user may know.
  const auto exported = writeVolumeExports(outputs, job.exports, volume, {1 / scale, "pixel"});
  if (!exported.empty()) written["exports"] = exported;
  outputs.write(job.output, [&](const std::string& path) { writeVdb(path, std::move(volume)); });

  nlohmann::json report = {{"solidtex_version", SOLIDTEX_VERSION},
                           {"command", "particles"},
                           {"seed", job.seed},
                           {"placer", placerName(job.placer)},
                           {"sizing", sizingName(job.sizing)},
                           {"arrangement", arrangementName(job.arrangement)},
                           {"boundary", boundaryName(job.boundary)},
                           {"matrix", matrixReport},
                           {"particle_texture", grainReport},
                           {"views", job.particles.views},
                           {"photo", toJson(stats)},
                           {"volume", placementJson(placement, stats, scale)},
                           {"outputs", written}};
  report["volume"]["particle_bin_ratios"] = sizing.binRatios;  // the share per bin placement aimed at
  report["volume"]["size_factor"] = sizing.sizeFactor;
  report["smoothing"] = {{"radius", smoothing.radius}, {"fitted", !job.smoothing.has_value()}};
  if (!job.smoothing) {
    report["smoothing"]["solidity_ks"] = smoothing.solidityKs;
    report["smoothing"]["roundness_ks"] = smoothing.roundnessKs;
  }
  if (job.sizing == Sizing::Sections) {
    report["volume"]["sizing_predicted_ks"] = sizing.predictedKs;
    const SizingUncertainty& u = sizing.uncertainty;
    report["volume"]["sizing_uncertainty"] = {{"bootstraps", u.bootstraps},
                                              {"size_factor_5_95", {u.sizeFactorLow, u.sizeFactorHigh}},
                                              {"mean_volume_relative_spread", u.meanVolumeSpread}};
  }
  report["time_seconds"] = timer.finish();
  report["peak_memory_mib"] = peakMemoryMiB();
  writeReport(outputs, job.report, report);
  outputs.commit();
  progress.done();
  return report;
}

}  // namespace solidtex
