#include "pipeline/analyzeJob.h"

#include "io/imageIO.h"
#include "pipeline/jobOutputs.h"
#include "pipeline/warnOfDroppedRegions.h"
#include "segmentation/drawLabels.h"
#include "segmentation/reportJson.h"

namespace solidtex {

nlohmann::json runAnalyze(const AnalyzeJob& job) {
  OutputFiles outputs;
  outputs.addInput(job.photo);
  if (job.segmentation.maskPath) outputs.addInput(*job.segmentation.maskPath);
  if (job.phases.maskPath) outputs.addInput(*job.phases.maskPath);
  if (job.labels) outputs.addFile("--labels", *job.labels, {".png"});
  addReport(outputs, job.report);
  const cv::Mat photo = loadPhoto(job.photo);
  nlohmann::json report;
  ExemplarStats stats = analyzeExemplar(photo, job.photo, job.segmentation);
  if (const std::optional<ParticlePhases> phases = findPhases(stats, job.phases, job.seed)) {
    assignPhases(stats, *phases);
    if (!phases->bic.empty()) report["phase_bic"] = phases->bic;
  }
  warnOfDroppedRegions(stats);
  report.update(toJson(stats));
  if (job.labels) {
    const cv::Mat labels = drawLabels(photo, stats);
    outputs.write(*job.labels, [&](const std::string& path) { writeImage(path, labels); });
  }
  writeReport(outputs, job.report, report);
  outputs.commit();
  return report;
}

}  // namespace solidtex
