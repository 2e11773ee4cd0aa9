#include "pipeline/spaciousnessJob.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/secondsSince.h"
#include "common/Error.h"
#include "particles/ParticleFactory.h"
#include "pipeline/jobSupport.h"
#include "pipeline/particleSolidJob.h"
#include "pipeline/spaciousnessPlot.h"
#include "placement/exactSpaciousness.h"
#include "placement/placeLargestFirst.h"
#include "segmentation/imageIO.h"

namespace solidtex {
namespace {

constexpr PlacerKind kKinds[] = {PlacerKind::Discrete, PlacerKind::Brute, PlacerKind::Edt, PlacerKind::Delaunay};

// Each particle's voxels, in id order: the order they were placed in.
std::vector<std::vector<Voxel>> voxelsPerParticle(const PlacementResult& placement) {
  std::vector<std::vector<Voxel>> out(placement.particles.size());
  for (std::size_t i = 0; i < placement.ids.size(); ++i)
    if (placement.ids[i] > 0) out[std::size_t(placement.ids[i] - 1)].push_back(placement.dims.voxel(i));
  return out;
}

nlohmann::json errorStats(std::vector<double> errors) {
  if (errors.empty()) return {{"count", 0}};
  double sum = 0, sumAbs = 0;
  const double largest = *std::max_element(errors.begin(), errors.end());
  for (double& e : errors) {
    sum += e;
    sumAbs += std::abs(e);
    e = std::abs(e);
  }
  const std::size_t p95 = std::min(errors.size() - 1, std::size_t(0.95 * double(errors.size())));
  std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(p95), errors.end());
  const double p95Value = errors[p95];
  const double n = double(errors.size());
  return {{"count", errors.size()},
          {"mean_error", sum / n},
          {"max_error", largest},
          {"mean_abs_error", sumAbs / n},
          {"p95_abs_error", p95Value},
          {"max_abs_error", *std::max_element(errors.begin(), errors.end())}};
}

// The smallest exact value of at least r over all voxels: where an exact best fit goes.
double exactBestFit(const std::vector<float>& exact, double r) {
  double best = INFINITY;
  for (const float e : exact)
    if (e >= r - 1e-6) best = std::min(best, double(e));
  return best;
}

double largestCandidate(const std::vector<std::pair<Voxel, float>>& candidates) {
  float largest = 0;
  for (const auto& [v, value] : candidates) largest = std::max(largest, value);
  return largest;
}

struct FieldRun {
  PlacerKind kind;
  std::unique_ptr<SpaciousnessField> field;
  double seconds = 0;
};

} // namespace

nlohmann::json runSpaciousness(const SpaciousnessJob& job) {
  if (job.size < 16 || job.size > 512) throw InputError("--size must be in [16, 512], got " + std::to_string(job.size));
  if (job.particles < 0) throw InputError("--particles must not be negative");
  ProgressLine progress(job.progress);
  const cv::Mat photo = loadPhoto(job.photo);
  const ExemplarStats stats = analyzeExemplar(photo, job.photo, job.segmentation);
  const Dims dims{job.size, job.size, job.size};
  const double scale = defaultVoxelsPerPixel(stats, dims);
  const float cap = placementRadiusCap(stats, scale);

  progress.update("placing particles");
  ParticleOptions particleOptions;
  particleOptions.seed = job.seed;
  const ParticleFactory factory(stats, particleOptions);
  PlacementOptions placementOptions;
  placementOptions.dims = dims;
  placementOptions.voxelsPerPixel = scale;
  placementOptions.seed = job.seed;
  placementOptions.maxParticles = job.particles;
  auto placer = makeSpaciousnessField(PlacerKind::Edt, dims, cap);
  const PlacementResult placement = placeLargestFirst(stats, factory, *placer, placementOptions);
  const auto particles = voxelsPerParticle(placement);

  std::vector<FieldRun> runs;
  for (const PlacerKind kind : kKinds) {
    progress.update(std::string("building the ") + placerName(kind) + " field");
    const auto start = std::chrono::steady_clock::now();
    FieldRun run{kind, makeSpaciousnessField(kind, dims, cap)};
    for (const auto& voxels : particles) run.field->insert(voxels);
    run.seconds = secondsSince(start);
    runs.push_back(std::move(run));
  }
  progress.update("exact distances");
  const auto exactStart = std::chrono::steady_clock::now();
  const std::vector<float> exact = exactSpaciousness(dims, placement.ids, cap);
  const double exactSeconds = secondsSince(exactStart);
  progress.done();

  Rng rng(deriveSeed(job.seed, 0x5Ac3));
  const std::vector<std::pair<Voxel, float>> circumcentres = runs.back().field->candidates();
  // Best fit is asked for balls up to the largest that still fits anywhere.
  const double largest = *std::max_element(exact.begin(), exact.end());
  const std::vector<double> radii = {0.25 * largest, 0.5 * largest, 0.75 * largest, largest};
  std::vector<double> exactBestFits;
  for (const double r : radii) exactBestFits.push_back(exactBestFit(exact, r));
  SpaciousnessErrors errors;
  nlohmann::json fields = nlohmann::json::object();
  for (FieldRun& run : runs) {
    std::vector<double> all, atCentres;
    for (std::size_t i = 0; i < exact.size(); ++i)
      if (placement.ids[i] == 0) all.push_back(double(run.field->at(dims.voxel(i))) - exact[i]);
    // At the circumcentres the Delaunay field is judged by the values its best fit ranks by.
    const bool ranksCandidates = run.kind == PlacerKind::Delaunay;
    for (const auto& [v, value] : circumcentres)
      atCentres.push_back(double(ranksCandidates ? value : run.field->at(v)) - exact[dims.index(v)]);
    nlohmann::json bestFits = nlohmann::json::array();
    for (std::size_t k = 0; k < radii.size(); ++k) {
      const double r = radii[k], target = exactBestFits[k];
      const std::vector<Voxel> spot = run.field->bestFit(float(r), 1, rng);
      const double got = spot.empty() ? NAN : double(exact[dims.index(spot[0])]);
      bestFits.push_back({{"radius", r},
                          {"exact_best_fit", std::isfinite(target) ? nlohmann::json(target) : nlohmann::json()},
                          {"exact_at_spot", spot.empty() ? nlohmann::json() : nlohmann::json(got)},
                          {"agrees", spot.empty() ? !std::isfinite(target)
                                                  : got >= r - run.field->slack() - 1e-6 && got - target <= 1.0}});
    }
    fields[placerName(run.kind)] = {{"seconds", run.seconds},
                                    {"all_voxels", errorStats(all)},
                                    {"circumcentres", errorStats(atCentres)},
                                    {"best_fit", bestFits}};
    // Delaunay's at() is a nearest-vertex bound; what it adds is its circumcentre candidates.
    if (ranksCandidates) errors.push_back({"delaunay (circumcentres)", atCentres, run.seconds});
    else errors.push_back({placerName(run.kind), all, run.seconds});
  }
  nlohmann::json report = {{"photo", job.photo},
                           {"dims", {dims.x, dims.y, dims.z}},
                           {"seed", job.seed},
                           {"particles", placement.particles.size()},
                           {"volume_fraction", placement.volumeFraction},
                           {"radius_cap", cap},
                           {"circumcentres", circumcentres.size()},
                           {"largest_exact_empty_ball", largest},
                           {"largest_circumsphere_candidate", largestCandidate(circumcentres)},
                           {"exact_seconds", exactSeconds},
                           {"fields", fields},
                           {"peak_memory_mib", peakMemoryMiB()}};
  if (job.plot) writeImage(*job.plot, plotSpaciousnessErrors(errors));
  if (job.report) writeJsonFile(*job.report, report);
  return report;
}

} // namespace solidtex
