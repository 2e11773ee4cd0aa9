#include "pipeline/analyzeJob.h"

#include "pipeline/jobSupport.h"
#include "segmentation/drawLabels.h"
#include "segmentation/imageIO.h"
#include "segmentation/reportJson.h"

namespace solidtex {

nlohmann::json runAnalyze(const AnalyzeJob& job) {
  const cv::Mat photo = loadPhoto(job.photo);
  const ExemplarStats stats = analyzeExemplar(photo, job.photo, job.segmentation);
  nlohmann::json report = toJson(stats);
  if (job.labels) writeImage(*job.labels, drawLabels(photo, stats));
  if (job.report) writeJsonFile(*job.report, report);
  return report;
}

}  // namespace solidtex
