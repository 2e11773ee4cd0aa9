#include "pipeline/synthesizeJob.h"

#include <array>
#include <filesystem>
#include <optional>
#include <utility>

#include "Version.h"
#include "common/Error.h"
#include "common/ProgressLine.h"
#include "common/memoryBudget.h"
#include "io/imageIO.h"
#include "io/vdbIO.h"
#include "pipeline/continuousQualityReport.h"
#include "pipeline/jobOutputs.h"
#include "synthesis/synthesizeSolid.h"
#include "validation/sectionStatistics.h"
#include "voxel/writePreviews.h"

namespace solidtex {

nlohmann::json synthesisReport(const SynthesisOptions& o, const SynthesisStatistics& stats,
                               const ContinuousQuality* quality,
                               const ContinuousQualityOptions& qualityOptions) {
  const LevelStatistics& finest = stats.levels.back();
  nlohmann::json report = {
      {"method", methodName(o.method)},
      {"size", o.size},
      {"levels", o.levels},
      {"neighborhoods", stats.neighborhoods},
      {"k", o.k},
      {"iterations", o.iterations},
      {"pca_dims", o.pcaDims},
      {"seed", o.seed},
      {"control", bool(o.control)},
      {"exemplar",
       {{"name", o.exemplarName}, {"width", finest.exemplarWidth}, {"height", finest.exemplarHeight}}}};
  if (o.method != Method::Kopf) report["color_histogram_matching"] = o.colorHistogramMatching;
  if (o.method == Method::Skeletal) report["wavelet_levels"] = o.waveletLevels;
  report["distance"] = distanceName(o.distance);
  report["periodic"] = true;  // every photo method synthesises on a torus (WorkVolume), flag or not
  nlohmann::json levels = nlohmann::json::array();
  for (std::size_t l = 0; l < stats.levels.size(); ++l) {
    const LevelStatistics& level = stats.levels[l];
    nlohmann::json iterations = nlohmann::json::array();
    for (std::size_t i = 0; i < level.iterations.size(); ++i) {
      const IterationStatistics& step = level.iterations[i];
      nlohmann::json entry = {{"iteration", i + 1},
                              {"energy", step.energy},
                              {"search_seconds", step.searchSeconds},
                              {"solve_seconds", step.solveSeconds}};
      if (step.positionCoverage) entry["position_coverage"] = *step.positionCoverage;
      iterations.push_back(entry);
    }
    nlohmann::json levelEntry = {{"level", l + 1},
                                 {"volume_size", level.volumeSize},
                                 {"exemplar_width", level.exemplarWidth},
                                 {"exemplar_height", level.exemplarHeight},
                                 {"neighborhood", level.neighborhood},
                                 {"exemplar_neighborhoods", level.exemplarNeighborhoods},
                                 {"pca_dims", level.pcaDims},
                                 {"pca_kept_variance", level.pcaKeptVariance},
                                 {"search", searchName(level.search)},
                                 {"analysis_seconds", level.analysisSeconds},
                                 {"iterations", iterations},
                                 {"seconds", level.seconds}};
    if (level.search == NeighborhoodSearch::KCoherence)
      levelEntry["similarity_sets"] = level.similarityLists
                                          ? nlohmann::json{{"search", "approximate"},
                                                           {"lists", level.similarityLists},
                                                           {"probes", level.similarityProbes}}
                                          : nlohmann::json{{"search", "exact"}};
    levels.push_back(levelEntry);
  }
  report["level_reports"] = levels;
  if (stats.indexCoverage) report["index_coverage"] = *stats.indexCoverage;
  if (stats.rebuildSeconds) report["rebuild_seconds"] = *stats.rebuildSeconds;
  if (quality) report["quality"] = continuousQualityJson(*quality, qualityOptions);
  report["seconds"] = stats.seconds;
  return report;
}

namespace {

/// The yz, xz and xy planes' exemplars when the job has plane exemplars.
std::optional<std::array<std::string, 3>> planeExemplarPaths(const SynthesizeJob& job) {
  if (!job.photoXz && !job.photoYz) return std::nullopt;
  return std::array<std::string, 3>{job.photoYz.value_or(*job.photoXz), job.photoXz.value_or(*job.photoYz),
                                    job.exemplar};
}

}  // namespace

nlohmann::json planeExemplarsReport(const SolidVolume& volume, const std::array<cv::Mat, 3>& planes,
                                    const std::array<std::string, 3>& names,
                                    const ContinuousQualityOptions* quality) {
  nlohmann::json out;
  for (int axis = 0; axis < 3; ++axis) {
    nlohmann::json& plane = out[planeNameOf(axis)];
    plane["exemplar"] = names[axis];
    if (!quality) continue;
    ContinuousQualityOptions options = *quality;
    options.planeAxis = axis;
    plane["quality"] =
        continuousQualityJson(measureContinuousSolid(volume, planes[axis], {}, options), options);
  }
  return out;
}

nlohmann::json runSynthesize(const SynthesizeJob& job) {
  namespace fs = std::filesystem;
  // Peak resident memory per voxel: 663 MiB for chen-wang at 256^3.
  constexpr double kBytesPerVoxel = 40;
  const int size = job.synthesis.size;
  requireVolumeMemory("synthesising a solid", {size, size, size}, kBytesPerVoxel);
  OutputFiles outputs;
  outputs.addInput(job.exemplar);
  if (job.control) outputs.addInput(*job.control);
  addVolumeOutputs(outputs, job.output, job.report, job.preview);
  addVolumeExports(outputs, job.exports);

  const cv::Mat exemplar = loadPhoto(job.exemplar);
  const std::optional<std::array<std::string, 3>> planePaths = planeExemplarPaths(job);
  std::array<cv::Mat, 3> planes;
  if (planePaths)
    for (int axis = 0; axis < 2; ++axis) {
      outputs.addInput((*planePaths)[axis]);
      planes[axis] = loadPhoto((*planePaths)[axis]);
    }
  planes[2] = exemplar;
  SynthesisOptions options = job.synthesis;
  options.exemplarName = fs::path(job.exemplar).filename().string();
  if (job.control) options.control = loadPhoto(*job.control);
  ProgressLine progress(job.progress);
  if (job.progress)
    options.progress = [&](const std::string& step, double fraction) { progress.update(step, fraction); };
  SynthesisResult result = planePaths ? synthesizeSolid(planes, options) : synthesizeSolid(exemplar, options);
  progress.done();

  result.volume.metadata["solidtex_version"] = SOLIDTEX_VERSION;
  result.volume.metadata["command_line"] = job.commandLine;
  result.volume.metadata["seed"] = std::to_string(options.seed);
  result.volume.metadata["exemplar"] = options.exemplarName;
  std::optional<ContinuousQuality> quality;
  if (job.measure && !planePaths) {
    progress.update("measuring the slices against the exemplar");
    quality = measureContinuousSolid(result.volume, exemplar, {}, job.quality);
    progress.done();
  }
  nlohmann::json report =
      synthesisReport(options, result.statistics, quality ? &*quality : nullptr, job.quality);
  if (planePaths) {
    std::array<std::string, 3> names;
    for (int axis = 0; axis < 3; ++axis) names[axis] = fs::path((*planePaths)[axis]).filename().string();
    for (int axis = 0; axis < 2; ++axis)
      result.volume.metadata["exemplar_" + planeNameOf(axis)] = names[axis];
    if (job.measure) progress.update("measuring each plane's slices against its exemplar");
    report["planes"] =
        planeExemplarsReport(result.volume, planes, names, job.measure ? &job.quality : nullptr);
    progress.done();
  }
  report["solidtex_version"] = SOLIDTEX_VERSION;
  report["command"] = "synthesize";
  report["outputs"] = {{"vdb", job.output}};
  if (job.preview)
    report["outputs"]["previews"] = writePreviews(outputs, *job.preview, exemplar, result.volume);
  const auto exported = writeVolumeExports(outputs, job.exports, result.volume, {1, "pixel"});
  if (!exported.empty()) report["outputs"]["exports"] = exported;
  outputs.write(job.output, [&](const std::string& path) { writeVdb(path, std::move(result.volume)); });
  report["peak_memory_mib"] = peakMemoryMiB();
  writeReport(outputs, job.report, report);
  outputs.commit();
  return report;
}

}  // namespace solidtex
