#include "pipeline/synthesizeTextureJob.h"

#include <filesystem>

#include "Version.h"
#include "common/Error.h"
#include "common/ProgressLine.h"
#include "common/memoryBudget.h"
#include "io/imageIO.h"
#include "pipeline/continuousQualityReport.h"
#include "pipeline/jobOutputs.h"

namespace solidtex {
namespace {

nlohmann::json levelsJson(const TextureSynthesisResult& r) {
  nlohmann::json levels = nlohmann::json::array();
  for (std::size_t l = 0; l < r.levels.size(); ++l) {
    const TextureLevelStatistics& s = r.levels[l];
    levels.push_back({{"level", l + 1},
                      {"width", s.width},
                      {"height", s.height},
                      {"exemplar_width", s.exemplarWidth},
                      {"exemplar_height", s.exemplarHeight},
                      {"neighborhood", s.neighborhood},
                      {"analysis_seconds", s.analysisSeconds},
                      {"energies", s.energies},
                      {"seconds", s.seconds}});
  }
  return levels;
}

}  // namespace

nlohmann::json runSynthesizeTexture(const SynthesizeTextureJob& job) {
  namespace fs = std::filesystem;
  OutputFiles outputs;
  outputs.addInput(job.exemplar);
  if (job.reference) outputs.addInput(*job.reference);
  outputs.addFile("-o", job.output, {".png"});
  addReport(outputs, job.report);
  const cv::Mat exemplar = loadPhoto(job.exemplar);
  const cv::Mat reference = job.reference ? loadPhoto(*job.reference) : cv::Mat();
  ProgressLine progress(job.progress);
  TextureSynthesisOptions options = job.synthesis;
  if (job.progress)
    options.progress = [&](const std::string& step, double fraction) { progress.update(step, fraction); };
  const TextureSynthesisResult result = synthesizeTexture(exemplar, options);
  const TextureSynthesisOptions& o = job.synthesis;
  nlohmann::json report = {
      {"solidtex_version", SOLIDTEX_VERSION},
      {"command", "synthesize2d"},
      {"method", textureMethodName(o.method)},
      {"exemplar", {{"name", job.exemplar}, {"width", exemplar.cols}, {"height", exemplar.rows}}},
      {"width", o.width},
      {"height", o.height},
      {"levels", o.levels},
      {"neighborhoods", result.neighborhoods},
      {"iterations", o.iterations},
      {"pca_dims", o.pcaDims},
      {"distance", distanceName(o.distance)},
      {"seed", o.seed},
      {"level_reports", levelsJson(result)},
      {"seconds", result.seconds}};
  if (o.method == TextureMethod::Skeletal)
    report.update(
        {{"wavelet_levels", o.waveletLevels}, {"rebuild_seconds", result.rebuildSeconds.value_or(0.0)}});
  if (job.measure) {
    progress.update("measuring the texture against the exemplar");
    const TextureQuality quality = measureTexture(result.image, exemplar, reference, job.quality);
    report["quality"] = textureQualityJson(quality, job.quality);
  }
  progress.done();
  report["peak_memory_mib"] = peakMemoryMiB();
  outputs.write(job.output, [&](const std::string& path) { writeImage(path, result.image); });
  report["outputs"] = {{"png", job.output}};
  writeReport(outputs, job.report, report);
  outputs.commit();
  return report;
}

}  // namespace solidtex
