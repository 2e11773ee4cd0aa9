#include "pipeline/synthesizeVolumeJob.h"

#include <cstdio>
#include <filesystem>
#include <utility>

#include <opencv2/core.hpp>

#include "Version.h"
#include "common/Error.h"
#include "common/ProgressLine.h"
#include "common/ThreadLimit.h"
#include "common/memoryBudget.h"
#include "common/srgb.h"
#include "io/frameFieldIO.h"
#include "io/vdbIO.h"
#include "parallel/Communicator.h"
#include "pipeline/jobOutputs.h"
#include "voxel/writePreviews.h"

namespace solidtex {
namespace {

// What a person looks at: densities as grey levels, colours as they are.
std::vector<Rgb> displayColors(const DenseVolume& v) {
  std::vector<Rgb> out(v.dims.count());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const float* x = &v.values[i * std::size_t(v.channels)];
    out[i] = v.channels == 3 ? Rgb{x[0], x[1], x[2]}
                             : Rgb{srgbToLinear(x[0]), srgbToLinear(x[0]), srgbToLinear(x[0])};
  }
  return out;
}

// The exemplar's middle z slice in sRGB, shown beside the solid's slices.
cv::Mat middleSlice(const DenseVolume& exemplar) {
  const std::vector<Rgb> colors = displayColors(exemplar);
  cv::Mat out(exemplar.dims.y, exemplar.dims.x, CV_32FC3);
  const int k = exemplar.dims.z / 2;
  for (int j = 0; j < exemplar.dims.y; ++j)
    for (int i = 0; i < exemplar.dims.x; ++i) {
      const Rgb& c = colors[exemplar.dims.index(i, j, k)];
      out.at<cv::Vec3f>(j, i) = {linearToSrgb(c[0]), linearToSrgb(c[1]), linearToSrgb(c[2])};
    }
  return out;
}

}  // namespace

std::optional<FrameField> loadVolumeField(const SynthesizeVolumeJob& job) {
  if (!job.field) return std::nullopt;
  if (std::filesystem::path(*job.field).extension() == ".vdb")
    return readFrameField(*job.field, job.synthesis.dims);
  return builtinFrameField(*job.field, job.synthesis.dims);
}

SolidVolume solidOfSynthesis(VolumeSynthesisResult&& result) {
  SolidVolume solid;
  solid.dims = result.values.dims;
  if (result.values.channels == 3) {
    solid.color.resize(solid.dims.count());
    for (std::size_t i = 0; i < solid.color.size(); ++i)
      solid.color[i] = {result.values.values[3 * i], result.values.values[3 * i + 1],
                        result.values.values[3 * i + 2]};
  } else {
    solid.density = std::move(result.values.values);
  }
  solid.sourceVoxel = std::move(result.source);
  solid.origin = result.box.lo;
  return solid;
}

std::vector<std::string> writeVolumePreviews(OutputFiles& outputs, const std::string& folder,
                                             const DenseVolume& exemplar, const SolidVolume& solid) {
  SolidVolume view;  // the colours only: the slices need nothing else
  view.dims = solid.dims;
  view.color = solid.color.empty() ? displayColors(DenseVolume{solid.dims, 1, solid.density}) : solid.color;
  return writePreviews(outputs, folder, middleSlice(exemplar), view);
}

namespace {

nlohmann::json levelReports(const VolumeSynthesisStatistics& stats) {
  nlohmann::json levels = nlohmann::json::array();
  for (std::size_t l = 0; l < stats.levels.size(); ++l) {
    const VolumeLevelStatistics& s = stats.levels[l];
    nlohmann::json entry = {{"level", l + 1},
                            {"spacing", s.spacing},
                            {"voxels", {s.synthesised.x, s.synthesised.y, s.synthesised.z}},
                            {"corrected", s.corrected},
                            {"seconds", s.seconds}};
    if (s.corrected) {
      entry["appearance_dims"] = s.appearanceDims;
      entry["pca_kept_variance"] = s.keptVariance;
      entry["similarity_fallback_share"] = s.similarityFallbackShare;
      entry["analysis_seconds"] = s.analysisSeconds;
    }
    levels.push_back(entry);
  }
  return levels;
}

nlohmann::json volumeQualityJson(const VolumeQuality& q) {
  return {{"coherence", q.coherence},
          {"completeness", q.completeness},
          {"shuffled_coherence", q.shuffledCoherence},
          {"shuffled_completeness", q.shuffledCompleteness},
          {"coherence_ratio", q.coherenceRatio()},
          {"completeness_ratio", q.completenessRatio()},
          {"slice_coherence", q.sliceCoherence},
          {"slice_completeness", q.sliceCompleteness},
          {"shuffled_slice_coherence", q.shuffledSliceCoherence},
          {"shuffled_slice_completeness", q.shuffledSliceCompleteness},
          {"slice_coherence_ratio", q.sliceCoherenceRatio()},
          {"value_wasserstein", q.valueWasserstein},
          {"exact_share", q.exactShare},
          {"seconds", q.seconds}};
}

// At most the central kMeasuredSide^3 box: the measure indexes every output patch, which a large
// output cannot afford (25 floats a voxel).
constexpr int kMeasuredSide = 128;

DenseVolume centralBox(const DenseVolume& v, int side) {
  const Dims d{std::min(v.dims.x, side), std::min(v.dims.y, side), std::min(v.dims.z, side)};
  if (d == v.dims) return v;
  const Voxel lo{(v.dims.x - d.x) / 2, (v.dims.y - d.y) / 2, (v.dims.z - d.z) / 2};
  DenseVolume out{d, v.channels, std::vector<float>(d.count() * std::size_t(v.channels))};
  for (int k = 0; k < d.z; ++k)
    for (int j = 0; j < d.y; ++j)
      std::copy_n(v.at(lo.x, lo.y + j, lo.z + k), std::size_t(d.x) * std::size_t(v.channels),
                  out.at(0, j, k));
  return out;
}

}  // namespace

nlohmann::json volumeQualityReport(const DenseVolume& output, const DenseVolume& exemplar,
                                   const VolumeQualityOptions& options) {
  const Dims& d = output.dims;
  if (std::min({d.x, d.y, d.z}) < options.patch)
    return {{"skipped", "the output is thinner than a " + std::to_string(options.patch) + "^3 patch"}};
  const DenseVolume measured = centralBox(output, kMeasuredSide);
  nlohmann::json quality = volumeQualityJson(measureVolumeQuality(measured, exemplar, options));
  quality["measured_voxels"] = {measured.dims.x, measured.dims.y, measured.dims.z};
  return quality;
}

DenseVolume readVolumeExemplar(const std::string& path) {
  SolidVolume v = readVdb(path);
  // Synthesis reads the whole box of active voxels: a few scattered voxels would make it a large,
  // empty exemplar that takes minutes to analyse and has no texture to copy.
  constexpr double kMinActiveShare = 0.01;
  const double activeShare = double(v.activeVoxels) / double(v.dims.count());
  if (activeShare < kMinActiveShare) {
    char share[32];
    std::snprintf(share, sizeof share, "%.3g%%", 100 * activeShare);
    throw InputError("cannot use " + path + " as an exemplar: its active voxels fill " + share +
                     " of their " + std::to_string(v.dims.x) + "x" + std::to_string(v.dims.y) + "x" +
                     std::to_string(v.dims.z) + " box; crop it to the material");
  }
  DenseVolume out;
  out.dims = v.dims;
  if (!v.color.empty()) {
    out.channels = 3;
    out.values.resize(v.color.size() * 3);
    for (std::size_t i = 0; i < v.color.size(); ++i) std::copy_n(v.color[i].data(), 3, &out.values[3 * i]);
  } else {
    out.values = std::move(v.density);
  }
  if (out.values.size() != out.dims.count() * std::size_t(out.channels))
    throw InputError("cannot read " + path +
                     ": its color grid is not Vec3s and its density grid is not float");
  return out;
}

nlohmann::json volumeSynthesisReport(const VolumeSynthesisResult& result,
                                     const VolumeSynthesisOptions& options, const DenseVolume& exemplar,
                                     const std::string& exemplarName, const std::string& fieldName) {
  nlohmann::json report = {{"solidtex_version", SOLIDTEX_VERSION},
                           {"command", "synthesize"},
                           {"method", "su-volume"},
                           {"exemplar",
                            {{"name", exemplarName},
                             {"dims", {exemplar.dims.x, exemplar.dims.y, exemplar.dims.z}},
                             {"channels", exemplar.channels},
                             {"domain", result.statistics.domain}}},
                           {"dims", {options.dims.x, options.dims.y, options.dims.z}},
                           {"field", fieldName},
                           {"jitter", options.jitter},
                           {"k", options.k},
                           {"exclusion", options.exclusion},
                           {"appearance", options.window},
                           {"pca_dims", options.pcaDims},
                           {"corrections", options.corrections},
                           {"periodic", options.periodic},
                           {"seed", options.seed}};
  if (options.region) {
    const Box& box = result.box;
    report["region"] = {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z};
  }
  report["level_reports"] = levelReports(result.statistics);
  report["analysis_seconds"] = result.statistics.analysisSeconds;
  report["seconds"] = result.statistics.seconds;
  return report;
}

std::map<std::string, std::string> volumeFileMetadata(const SynthesizeVolumeJob& job) {
  return {{"solidtex_version", SOLIDTEX_VERSION},
          {"command_line", job.commandLine},
          {"seed", std::to_string(job.synthesis.seed)},
          {"exemplar", std::filesystem::path(job.exemplar).filename().string()}};
}

nlohmann::json runSynthesizeVolume(const SynthesizeVolumeJob& job) {
  namespace fs = std::filesystem;
  if (job.brickEdge != 0 || launchedAs().size > 1) return runBrickedVolumeSynthesis(job);
  // Peak resident memory per voxel: 981 MiB for the walnut solid at 256^3; a frame field adds its
  // three axes per voxel.
  constexpr double kBytesPerVoxel = 56, kFieldBytesPerVoxel = 36;
  const auto& o = job.synthesis;
  requireVolumeMemory("synthesising a volume", o.region ? o.region->dims() : o.dims, kBytesPerVoxel);
  if (job.field) requireVolumeMemory("its frame field", o.dims, kFieldBytesPerVoxel);
  OutputFiles outputs;
  outputs.addInput(job.exemplar);
  if (job.field) outputs.addInput(*job.field);
  addVolumeOutputs(outputs, job.output, job.report, job.preview);
  addVolumeExports(outputs, job.exports);

  const ThreadLimit threads(job.synthesis.threads);
  const DenseVolume exemplar = readVolumeExemplar(job.exemplar);
  const std::optional<FrameField> field = loadVolumeField(job);
  VolumeSynthesisOptions options = job.synthesis;
  options.field = field ? &*field : nullptr;
  ProgressLine progress(job.progress);
  if (job.progress)
    options.progress = [&](const std::string& step, double fraction) { progress.update(step, fraction); };
  VolumeSynthesisResult result = synthesizeFromVolume(exemplar, options);
  progress.done();

  nlohmann::json report = volumeSynthesisReport(
      result, options, exemplar, fs::path(job.exemplar).filename().string(), job.field.value_or("none"));
  if (job.measure) {
    progress.update("measuring the volume against the exemplar");
    report["quality"] = volumeQualityReport(result.values, exemplar, job.quality);
    progress.done();
  }
  SolidVolume solid = solidOfSynthesis(std::move(result));
  solid.metadata = volumeFileMetadata(job);
  report["outputs"] = {{"vdb", job.output}};
  if (job.preview)
    report["outputs"]["previews"] = writeVolumePreviews(outputs, *job.preview, exemplar, solid);
  const auto exported = writeVolumeExports(outputs, job.exports, solid, {1, "voxel"});
  if (!exported.empty()) report["outputs"]["exports"] = exported;
  outputs.write(job.output, [&](const std::string& path) { writeVdb(path, std::move(solid)); });
  report["peak_memory_mib"] = peakMemoryMiB();
  writeReport(outputs, job.report, report);
  outputs.commit();
  return report;
}

}  // namespace solidtex
