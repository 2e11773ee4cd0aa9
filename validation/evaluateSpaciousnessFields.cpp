#include "validation/evaluateSpaciousnessFields.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "common/Random.h"
#include "common/secondsSince.h"
#include "placement/exactSpaciousness.h"

namespace solidtex {
namespace {

// Each particle's voxels, in id order: the order they were placed in.
std::vector<std::vector<Voxel>> voxelsPerParticle(const Dims& dims, const std::vector<std::int32_t>& ids) {
  const std::int32_t count = ids.empty() ? 0 : *std::max_element(ids.begin(), ids.end());
  std::vector<std::vector<Voxel>> out(std::size_t(std::max(count, 0)));
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (ids[i] > 0) out[std::size_t(ids[i] - 1)].push_back(dims.voxel(i));
  return out;
}

// A particle of a periodic volume that crosses a face, made whole again: on each axis its
// coordinates are moved past the face where the widest gap between them lies, as a field takes a
// particle (a split one would look as wide as the volume, and be updated from all its images).
void unwrap(std::vector<Voxel>& voxels, const Dims& dims) {
  const auto alongAxis = [&](int Voxel::*axis, int n) {
    std::vector<std::uint8_t> used(std::size_t(n), 0);
    for (const Voxel& v : voxels) used[std::size_t(v.*axis)] = 1;
    int gapEnd = 0, widest = -1;  // the first used coordinate after the widest run of unused ones
    for (int start = 0; start < n; ++start) {
      if (used[std::size_t(start)] || used[std::size_t((start + n - 1) % n)] == 0) continue;
      int length = 0;
      while (length < n && used[std::size_t((start + length) % n)] == 0) ++length;
      if (length > widest) widest = length, gapEnd = (start + length) % n;
    }
    if (widest <= 0) return;
    for (Voxel& v : voxels)
      if (v.*axis < gapEnd) v.*axis += n;
  };
  alongAxis(&Voxel::x, dims.x);
  alongAxis(&Voxel::y, dims.y);
  alongAxis(&Voxel::z, dims.z);
}

// The smallest exact value of at least r over all voxels: where an exact best fit goes.
std::optional<double> exactBestFit(const std::vector<float>& exact, double r) {
  double best = INFINITY;
  for (const float e : exact)
    if (e >= r - 1e-6) best = std::min(best, double(e));
  return std::isfinite(best) ? std::optional(best) : std::nullopt;
}

double largestCandidate(const std::vector<std::pair<Voxel, float>>& candidates) {
  float largest = 0;
  for (const auto& [v, value] : candidates) largest = std::max(largest, value);
  return largest;
}

}  // namespace

ErrorSummary summarizeErrors(std::vector<double> errors) {
  ErrorSummary summary;
  summary.count = errors.size();
  if (errors.empty()) return summary;
  double sum = 0, sumAbs = 0;
  summary.maxError = *std::max_element(errors.begin(), errors.end());
  for (double& e : errors) {
    sum += e;
    sumAbs += std::abs(e);
    e = std::abs(e);
  }
  const std::size_t p95 = std::min(errors.size() - 1, std::size_t(0.95 * double(errors.size())));
  std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(p95), errors.end());
  const double n = double(errors.size());
  summary.meanError = sum / n;
  summary.meanAbsError = sumAbs / n;
  summary.p95AbsError = errors[p95];
  summary.maxAbsError = *std::max_element(errors.begin(), errors.end());
  return summary;
}

SpaciousnessEvaluation evaluateSpaciousnessFields(const Dims& dims, const std::vector<std::int32_t>& ids,
                                                  float radiusCap, std::uint64_t seed,
                                                  const std::function<void(const std::string&)>& progress,
                                                  bool periodic) {
  if (dims.count() == 0 || ids.size() != dims.count())
    throw std::invalid_argument(
        "evaluateSpaciousnessFields: the ids must be one per voxel of a non-empty volume");
  const auto tell = [&](const std::string& step) {
    if (progress) progress(step);
  };
  auto particles = voxelsPerParticle(dims, ids);
  if (periodic)
    for (auto& voxels : particles) unwrap(voxels, dims);
  SpaciousnessEvaluation evaluation;
  std::vector<std::unique_ptr<SpaciousnessField>> built;
  for (const PlacerKind kind : placerKinds()) {
    tell(std::string("building the ") + placerName(kind) + " field");
    const auto start = std::chrono::steady_clock::now();
    built.push_back(makeSpaciousnessField(kind, dims, radiusCap, periodic));
    for (const auto& voxels : particles) built.back()->insert(voxels);
    evaluation.fields.push_back({kind, secondsSince(start)});
  }
  tell("exact distances");
  const auto exactStart = std::chrono::steady_clock::now();
  const std::vector<float> exact = exactSpaciousness(dims, ids, radiusCap, periodic);
  evaluation.exactSeconds = secondsSince(exactStart);

  Rng rng(deriveSeed(seed, 0x5Ac3));
  const std::vector<std::pair<Voxel, float>> circumcentres = built.back()->candidates();
  evaluation.circumcentres = circumcentres.size();
  evaluation.largestCircumsphereCandidate = largestCandidate(circumcentres);
  // Best fit is asked for balls up to the largest that still fits anywhere.
  const double largest = *std::max_element(exact.begin(), exact.end());
  evaluation.largestExactEmptyBall = largest;
  std::vector<BestFitCheck> exactFits;
  for (const double share : {0.25, 0.5, 0.75, 1.0})
    exactFits.push_back({share * largest, exactBestFit(exact, share * largest)});
  tell("measuring the fields");
  for (std::size_t f = 0; f < built.size(); ++f) {
    SpaciousnessField& field = *built[f];
    FieldEvaluation& result = evaluation.fields[f];
    std::vector<double> free, atCentres;
    for (std::size_t i = 0; i < exact.size(); ++i)
      if (ids[i] == 0) free.push_back(double(field.at(dims.voxel(i))) - exact[i]);
    const bool ranksCandidates = result.kind == PlacerKind::Delaunay;
    for (const auto& [v, value] : circumcentres)
      atCentres.push_back(double(ranksCandidates ? value : field.at(v)) - exact[dims.index(v)]);
    result.freeVoxels = summarizeErrors(free);
    result.circumcentres = summarizeErrors(atCentres);
    result.errors = std::move(ranksCandidates ? atCentres : free);
    for (BestFitCheck check : exactFits) {
      const double r = check.radius;
      const std::vector<Voxel> spot = field.bestFit(float(r), 1, rng);
      if (!spot.empty()) check.exactAtSpot = double(exact[dims.index(spot[0])]);
      check.agrees = check.exactAtSpot
                         ? *check.exactAtSpot >= r - field.slack() - 1e-6 &&
                               (!check.exactBestFit || *check.exactAtSpot - *check.exactBestFit <= 1.0)
                         : !check.exactBestFit;
      result.bestFits.push_back(check);
    }
  }
  return evaluation;
}

}  // namespace solidtex
