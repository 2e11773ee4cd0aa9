#include "pipeline/spaciousnessJob.h"

#include "common/Error.h"
#include "common/ProgressLine.h"
#include "common/memoryBudget.h"
#include "io/imageIO.h"
#include "particleSolid/makeParticleSolid.h"
#include "particles/ParticleFactory.h"
#include "pipeline/jobOutputs.h"
#include "pipeline/spaciousnessPlot.h"
#include "placement/placeLargestFirst.h"
#include "validation/evaluateSpaciousnessFields.h"

namespace solidtex {
namespace {

nlohmann::json toJson(const ErrorSummary& s) {
  if (s.count == 0) return {{"count", 0}};
  return {{"count", s.count},
          {"mean_error", s.meanError},
          {"max_error", s.maxError},
          {"mean_abs_error", s.meanAbsError},
          {"p95_abs_error", s.p95AbsError},
          {"max_abs_error", s.maxAbsError}};
}

nlohmann::json toJson(const BestFitCheck& check) {
  const auto optional = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json();
  };
  return {{"radius", check.radius},
          {"exact_best_fit", optional(check.exactBestFit)},
          {"exact_at_spot", optional(check.exactAtSpot)},
          {"agrees", check.agrees}};
}

}  // namespace

nlohmann::json runSpaciousness(const SpaciousnessJob& job) {
  if (job.size < 16 || job.size > 512)
    throw OptionError("--size must be in [16, 512], got " + std::to_string(job.size));
  if (job.particles < 0) throw OptionError("--particles must not be negative");
  OutputFiles outputs;
  outputs.addInput(job.photo);
  if (job.segmentation.maskPath) outputs.addInput(*job.segmentation.maskPath);
  if (job.plot) outputs.addFile("--plot", *job.plot, {".png"});
  addReport(outputs, job.report);
  ProgressLine progress(job.progress);
  const cv::Mat photo = loadPhoto(job.photo);
  const ExemplarStats stats = analyzeExemplar(photo, job.photo, job.segmentation);
  const Dims dims{job.size, job.size, job.size};
  const double scale = defaultVoxelsPerPixel(largestBoxSide(stats), dims);
  const float cap = placementRadiusCap(largestBoxSide(stats), scale);

  progress.update("placing particles");
  ParticleOptions particleOptions;
  particleOptions.seed = job.seed;
  const ParticleFactory factory(stats, particleOptions);
  PlacementOptions placementOptions;
  placementOptions.dims = dims;
  placementOptions.voxelsPerPixel = scale;
  placementOptions.seed = job.seed;
  placementOptions.maxParticles = job.particles;
  placementOptions.periodic = job.periodic;
  auto placer = makeSpaciousnessField(PlacerKind::Edt, dims, cap, job.periodic);
  const PlacementResult placement = placeLargestFirst(stats, factory, *placer, placementOptions);
  SpaciousnessEvaluation evaluation = evaluateSpaciousnessFields(
      dims, placement.ids, cap, job.seed, [&](const std::string& step) { progress.update(step); },
      job.periodic);
  progress.done();

  SpaciousnessErrors errors;
  nlohmann::json fields = nlohmann::json::object();
  for (FieldEvaluation& field : evaluation.fields) {
    nlohmann::json bestFits = nlohmann::json::array();
    for (const BestFitCheck& check : field.bestFits) bestFits.push_back(toJson(check));
    fields[placerName(field.kind)] = {{"seconds", field.seconds},
                                      {"all_voxels", toJson(field.freeVoxels)},
                                      {"circumcentres", toJson(field.circumcentres)},
                                      {"best_fit", bestFits}};
    const std::string name =
        field.kind == PlacerKind::Delaunay ? "delaunay (circumcentres)" : placerName(field.kind);
    errors.push_back({name, std::move(field.errors)});
  }
  nlohmann::json report = {{"photo", job.photo},
                           {"dims", {dims.x, dims.y, dims.z}},
                           {"seed", job.seed},
                           {"periodic", job.periodic},
                           {"particles", placement.particles.size()},
                           {"volume_fraction", placement.volumeFraction},
                           {"radius_cap", cap},
                           {"circumcentres", evaluation.circumcentres},
                           {"largest_exact_empty_ball", evaluation.largestExactEmptyBall},
                           {"largest_circumsphere_candidate", evaluation.largestCircumsphereCandidate},
                           {"exact_seconds", evaluation.exactSeconds},
                           {"fields", fields},
                           {"peak_memory_mib", peakMemoryMiB()}};
  if (job.plot) {
    const cv::Mat plot = plotSpaciousnessErrors(errors);
    outputs.write(*job.plot, [&](const std::string& path) { writeImage(path, plot); });
  }
  writeReport(outputs, job.report, report);
  outputs.commit();
  return report;
}

}  // namespace solidtex
