#include "pipeline/growSolidJob.h"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "Version.h"
#include "common/ProgressLine.h"
#include "common/memoryBudget.h"
#include "io/imageIO.h"
#include "io/vdbIO.h"
#include "pipeline/continuousQualityReport.h"
#include "pipeline/jobOutputs.h"
#include "pipeline/synthesizeJob.h"
#include "voxel/writePreviews.h"

namespace solidtex {
namespace {

// Measured peaks (docs/performance.md). The analysis holds the seed solid and searches each
// level's similarity sets: 48 nearest ids and distances per domain voxel, and the features and their
// index; it keeps 16 features and 3 similar voxels per domain voxel and level. The growth holds more
// beside it (the writing's buffers), the output's colours (and the grid they become, written in
// slabs), and per voxel of a brick's finest window and of the brick itself.
constexpr double kMiB = 1024.0 * 1024;
constexpr double kAnalysisBaseBytes = 150 * kMiB, kSearchBytesPerDomainVoxel = 578;
constexpr double kKeptBytesPerAnalysedVoxel = 76;
constexpr double kGrowthBaseBytes = 250 * kMiB;
constexpr double kOutputBytesPerVoxel = 13, kWindowBytesPerVoxel = 10, kBrickBytesPerVoxel = 14;

// The quality is measured on at most the central kMeasuredSide^3 box: the measure holds an sRGB copy
// of what it reads, which the largest volumes have no room for.
constexpr int kMeasuredSide = 256;

SolidVolume centralBox(const SolidVolume& v, int side) {
  const Dims d{std::min(v.dims.x, side), std::min(v.dims.y, side), std::min(v.dims.z, side)};
  const Voxel lo{(v.dims.x - d.x) / 2, (v.dims.y - d.y) / 2, (v.dims.z - d.z) / 2};
  SolidVolume out;
  out.dims = d;
  out.color.reserve(d.count());
  for (int k = 0; k < d.z; ++k)
    for (int j = 0; j < d.y; ++j) {
      const auto row = v.color.begin() + std::ptrdiff_t(v.dims.index(lo.x, lo.y + j, lo.z + k));
      out.color.insert(out.color.end(), row, row + d.x);
    }
  return out;
}

double voxels(const Dims& d) { return double(d.x) * double(d.y) * double(d.z); }

nlohmann::json growthReport(const GrowOptions& o, const GrowResult& r) {
  const VolumeSynthesisOptions& v = o.volume;
  return {{"method", "su-volume"},
          {"dims", {v.dims.x, v.dims.y, v.dims.z}},
          {"seed_domain", r.seedDomain},
          {"jitter", v.jitter},
          {"k", v.k},
          {"exclusion", v.exclusion},
          {"appearance", v.window},
          {"pca_dims", v.pcaDims},
          {"corrections", v.corrections},
          {"brick_edge", o.brickEdge},
          {"bricks", r.bricks},
          {"finest_voxels_corrected", r.finestVoxels},
          {"analysis_seconds", r.analysisSeconds},
          {"seconds", r.growthSeconds}};
}

}  // namespace

double growPeakBytes(const Dims& dims, int edge, int margin, const VolumeAnalysisSize& seed) {
  const Dims brick =
      edge <= 0 ? dims : Dims{std::min(edge, dims.x), std::min(edge, dims.y), std::min(edge, dims.z)};
  const Dims window{std::min(brick.x + 2 * margin, dims.x), std::min(brick.y + 2 * margin, dims.y),
                    std::min(brick.z + 2 * margin, dims.z)};
  const double kept = kKeptBytesPerAnalysedVoxel * seed.levels * seed.domainVoxels;
  // The analysis's search is over before the output is made.
  return std::max(kAnalysisBaseBytes + kept + kSearchBytesPerDomainVoxel * seed.domainVoxels,
                  kGrowthBaseBytes + kept + kOutputBytesPerVoxel * voxels(dims) +
                      kWindowBytesPerVoxel * voxels(window) + kBrickBytesPerVoxel * voxels(brick));
}

int growBrickEdge(const Dims& dims, int margin, const VolumeAnalysisSize& seed, double availableBytes) {
  if (growPeakBytes(dims, 0, margin, seed) <= availableBytes) return 0;
  for (const int edge : {512, 256, 128})
    if (growPeakBytes(dims, edge, margin, seed) <= availableBytes) return edge;
  return 64;
}

int growSeedEdge(std::optional<int> growFrom, bool dimsGiven, const Dims& dims) {
  if (growFrom) return *growFrom;
  return dimsGiven || std::max({dims.x, dims.y, dims.z}) > kLargestDirectPhotoSolid ? kDefaultGrowSeed : 0;
}

double planGrowthMemory(GrowOptions& options) {
  const Dims& dims = options.volume.dims;
  const int margin = correctionMargin(options.volume.corrections);
  const int edge = options.seed.size;
  const VolumeAnalysisSize seed = volumeAnalysisSize({edge, edge, edge}, options.volume);
  if (options.brickEdge <= 0)
    options.brickEdge = growBrickEdge(dims, margin, seed, double(availableMemoryBytes()));
  const double bytes = growPeakBytes(dims, options.brickEdge, margin, seed);
  requireVolumeBytes("growing a solid", dims, bytes);
  return bytes;
}

ContinuousQuality measureGrownSolid(const SolidVolume& volume, const cv::Mat& photoSrgb,
                                    const ContinuousQualityOptions& options) {
  return measureContinuousSolid(centralBox(volume, kMeasuredSide), photoSrgb, {}, options);
}

nlohmann::json grownSolidReport(const GrowOptions& options, const GrowResult& result,
                                const ContinuousQuality* quality,
                                const ContinuousQualityOptions& qualityOptions) {
  SynthesisOptions seedOptions = options.seed;
  seedOptions.seed = options.volume.seed;
  const Dims& dims = options.volume.dims;
  nlohmann::json report = {{"solidtex_version", SOLIDTEX_VERSION},
                           {"command", "synthesize"},
                           {"method", "grown"},
                           {"dims", {dims.x, dims.y, dims.z}},
                           {"seed", options.volume.seed},
                           {"seed_solid", synthesisReport(seedOptions, result.seed)},
                           {"growth", growthReport(options, result)},
                           {"seconds", result.seed.seconds + result.analysisSeconds + result.growthSeconds}};
  if (quality) {
    report["quality"] = continuousQualityJson(*quality, qualityOptions);
    report["quality"]["measured_voxels"] = {std::min(dims.x, kMeasuredSide), std::min(dims.y, kMeasuredSide),
                                            std::min(dims.z, kMeasuredSide)};
  }
  return report;
}

nlohmann::json runGrowSolid(const GrowSolidJob& job) {
  namespace fs = std::filesystem;
  GrowOptions options = job.grow;
  const double estimate = planGrowthMemory(options);
  OutputFiles outputs;
  outputs.addInput(job.exemplar);
  addVolumeOutputs(outputs, job.output, job.report, job.preview);
  addVolumeExports(outputs, job.exports);

  const cv::Mat photo = loadPhoto(job.exemplar);
  options.seed.exemplarName = fs::path(job.exemplar).filename().string();
  ProgressLine progress(job.progress);
  if (job.progress)
    options.progress = [&](const std::string& step, double fraction) { progress.update(step, fraction); };
  GrowResult result = growSolid(photo, options);
  progress.done();

  SolidVolume& volume = result.volume;
  volume.metadata["solidtex_version"] = SOLIDTEX_VERSION;
  volume.metadata["command_line"] = job.commandLine;
  volume.metadata["seed"] = std::to_string(options.volume.seed);
  volume.metadata["exemplar"] = options.seed.exemplarName;
  std::optional<ContinuousQuality> quality;
  if (job.measure) {
    progress.update("measuring the slices against the exemplar");
    quality = measureGrownSolid(volume, photo, job.quality);
    progress.done();
  }
  nlohmann::json report = grownSolidReport(options, result, quality ? &*quality : nullptr, job.quality);
  report["outputs"] = {{"vdb", job.output}};
  if (job.preview) report["outputs"]["previews"] = writePreviews(outputs, *job.preview, photo, volume);
  const auto exported = writeVolumeExports(outputs, job.exports, volume, {1, "pixel"});
  if (!exported.empty()) report["outputs"]["exports"] = exported;
  outputs.write(job.output, [&](const std::string& path) { writeVdb(path, std::move(volume)); });
  report["peak_memory_mib"] = peakMemoryMiB();
  report["memory_estimate_mib"] = estimate / (1024.0 * 1024.0);
  writeReport(outputs, job.report, report);
  outputs.commit();
  return report;
}

}  // namespace solidtex
