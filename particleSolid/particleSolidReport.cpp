#include "particleSolid/particleSolidReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <vector>

#include "Version.h"
#include "common/distributionDistance.h"
#include "segmentation/reportJson.h"

namespace solidtex {
namespace {

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

nlohmann::json wholeVolumesJson(const WholeParticleVolumes& whole) {
  std::vector<double> sorted = whole.volumes;
  std::sort(sorted.begin(), sorted.end());
  nlohmann::json quantiles;
  for (int percent : {5, 10, 25, 50, 75, 90, 95, 99})
    quantiles[std::to_string(percent)] = quantileOfSorted(sorted, percent / 100.0);
  return {{"count", sorted.size()},
          {"mean_volume", mean(sorted)},
          {"volume_quantiles", quantiles},
          {"cut_particles", whole.cutParticles},
          {"cut_share", whole.cutShare}};
}

nlohmann::json bricksJson(const BrickedPlacementResult& bricked, int edge, int processes) {
  // Seconds each process spent placing its bricks: the slowest against the mean is the imbalance.
  std::vector<double> perProcess(std::size_t(processes), 0.0);
  for (const BrickPlacement& b : bricked.bricks) perProcess[std::size_t(b.rank)] += b.seconds;
  const double slowest = *std::max_element(perProcess.begin(), perProcess.end());
  const double total = std::max(1e-9, std::accumulate(perProcess.begin(), perProcess.end(), 0.0));
  nlohmann::json perBrick = nlohmann::json::array();
  double sum = 0, sumOfSquares = 0;
  for (const BrickPlacement& b : bricked.bricks) {
    perBrick.push_back(
        {{"box", {{b.brick.lo.x, b.brick.lo.y, b.brick.lo.z}, {b.brick.hi.x, b.brick.hi.y, b.brick.hi.z}}},
         {"colour", b.colour},
         {"process", b.rank},
         {"particles", b.particles},
         {"volume_fraction", b.volumeFraction},
         {"seconds", b.seconds},
         {"stop_reason", b.stopReason}});
    sum += b.volumeFraction;
    sumOfSquares += b.volumeFraction * b.volumeFraction;
  }
  const double n = double(bricked.bricks.size()), mean = sum / n;
  return {{"edge", edge},
          {"count", bricked.bricks.size()},
          {"halo", bricked.halo},
          {"rounds", bricked.rounds},
          {"processes", processes},
          {"per_process_seconds", perProcess},
          {"load_imbalance", slowest / (total / double(processes))},
          {"bytes_exchanged", bricked.bytesExchanged},
          {"colour_seconds", bricked.colourSeconds},
          {"volume_fraction_spread", std::sqrt(std::max(0.0, sumOfSquares / n - mean * mean))},
          {"per_brick", perBrick}};
}

nlohmann::json textureJson(const TextureChoice& choice) {
  nlohmann::json json = {{"texture", textureName(choice.texture)}};
  if (choice.block > 0) json["block"] = choice.block;
  if (!choice.reason.empty()) json["reason"] = choice.reason;
  return json;
}

// Each phase's colour, share of the photo and of the volume, particles in both.
nlohmann::json phasesJson(const ParticleSolid& solid) {
  const ExemplarStats& stats = solid.stats;
  const int phases = stats.phaseCentres.rows;
  const std::vector<double> photoFractions = phaseAreaFractions(stats);
  std::vector<int> photoParticles(std::size_t(phases), 0), placed(std::size_t(phases), 0);
  std::vector<double> voxels(std::size_t(phases), 0.0);
  for (const Particle2D& p : stats.particles) ++photoParticles[std::size_t(p.phase)];
  for (const PlacedParticle& p : solid.placement.particles) {
    const auto phase = std::size_t(stats.particles[std::size_t(p.source)].phase);
    ++placed[phase];
    voxels[phase] += double(p.voxelCount);
  }
  const double all = double(solid.placement.counted.dims().count());
  nlohmann::json classes = nlohmann::json::array();
  const nlohmann::json centres = phaseColoursJson(stats.phaseCentres);
  const nlohmann::json grain = phaseGrainJson(stats.phaseCentres);
  for (std::size_t k = 0; k < std::size_t(phases); ++k)
    classes.push_back({{"phase", k + 1},
                       {"lab", centres[k]},
                       {"grain", grain.is_null() ? nullptr : grain[k]},
                       {"photo_particles", photoParticles[k]},
                       {"area_fraction", photoFractions[k]},
                       {"particles", placed[k]},
                       {"volume_fraction", all > 0 ? voxels[k] / all : 0.0}});
  for (std::size_t k = 0; k < solid.phaseSizeFactors.size(); ++k)
    classes[k]["size_factor"] = solid.phaseSizeFactors[k];
  nlohmann::json out = {{"method", solid.phases.method}, {"count", phases}, {"classes", classes}};
  if (!solid.phases.bic.empty()) out["bic"] = solid.phases.bic;
  return out;
}

}  // namespace

std::map<std::string, std::string> particleSolidMetadata(const ParticleSolid& solid,
                                                         const ParticleSolidOptions& options,
                                                         const std::string& commandLine) {
  char fraction[32], voxelsPerPixel[32];
  std::snprintf(fraction, sizeof fraction, "%.6f", solid.placement.volumeFraction);
  std::snprintf(voxelsPerPixel, sizeof voxelsPerPixel, "%.9g", solid.voxelsPerPixel);
  std::map<std::string, std::string> metadata = {
      {"solidtex_version", SOLIDTEX_VERSION},
      {"command_line", commandLine},
      {"seed", std::to_string(options.seed)},
      {"exemplar", std::filesystem::path(solid.stats.name).filename().string()},
      {"volume_fraction", fraction},
      {"voxels_per_pixel", voxelsPerPixel},
      {"placer", placerName(options.placer)},
      {"sizing", sizingName(options.sizing)},
      {"arrangement", arrangementName(options.arrangement)},
      {"boundary", boundaryName(options.boundary)},
      {"size_factor", std::to_string(solid.sizing.sizeFactor)},
      {"smoothing", std::to_string(solid.smoothing.radius)},
      {"body_form", std::to_string(solid.bodyForm.form)}};
  addWholeVolumesMetadata(solid.wholeVolumes, metadata);
  if (solid.planeStats.size() == 2) {
    metadata["exemplar_xz"] = std::filesystem::path(solid.planeStats[0].name).filename().string();
    metadata["exemplar_yz"] = std::filesystem::path(solid.planeStats[1].name).filename().string();
  }
  if (solid.stats.phaseCentres.rows > 1) {
    metadata["phase_lab"] = phaseColoursJson(solid.stats.phaseCentres).dump();
    if (solid.stats.phaseCentres.cols > 3)
      metadata["phase_grain"] = phaseGrainJson(solid.stats.phaseCentres).dump();
  }
  const SizingUncertainty& u = solid.sizing.uncertainty;
  if (!u.bandVolumes.empty())
    metadata["particle_volume_cdf_band"] =
        nlohmann::json{{"volumes", u.bandVolumes}, {"cdf_5", u.bandLow}, {"cdf_95", u.bandHigh}}.dump();
  return metadata;
}

nlohmann::json particleSolidReport(const ParticleSolid& solid, const ParticleSolidOptions& options) {
  nlohmann::json report = {{"solidtex_version", SOLIDTEX_VERSION},
                           {"command", "particles"},
                           {"seed", options.seed},
                           {"placer", placerName(options.placer)},
                           {"sizing", sizingName(options.sizing)},
                           {"arrangement", arrangementName(options.arrangement)},
                           {"boundary", boundaryName(options.boundary)},
                           {"matrix", textureJson(solid.matrix)},
                           {"particle_texture", textureJson(solid.particleTexture)},
                           {"views", solid.planeStats.empty() ? options.particles.views : 3},
                           {"photo", toJson(solid.stats)},
                           {"volume", placementJson(solid.placement, solid.stats, solid.voxelsPerPixel)}};
  if (solid.planeStats.size() == 2) {
    report["photo_xz"] = toJson(solid.planeStats[0]);
    report["photo_yz"] = toJson(solid.planeStats[1]);
    report["volume"]["target_fraction"] = targetVolumeFraction(solid);
  }
  if (solid.stats.phaseCentres.rows > 1) report["phases"] = phasesJson(solid);
  if (solid.bricks)
    report["bricks"] = bricksJson(*solid.bricks, options.brickEdge, std::max(1, options.brickTeam.size));
  const SectionSizing& sizing = solid.sizing;
  // Voxels of every placed particle whose centre lies in the volume, before its faces cut it.
  report["volume"]["placed_particles"] = wholeVolumesJson(solid.wholeVolumes);
  report["volume"]["particle_bin_ratios"] = sizing.binRatios;  // the share per bin placement aimed at
  report["volume"]["size_factor"] = sizing.sizeFactor;
  const bool formFitted = !options.bodyForm && solid.planeStats.empty();  // aligned boxes keep their form
  report["body_form"] = {{"form", solid.bodyForm.form}, {"fitted", formFitted}};
  if (formFitted) report["body_form"]["aspect_ks"] = solid.bodyForm.aspectKs;
  report["smoothing"] = {{"radius", solid.smoothing.radius}, {"fitted", !options.smoothing.has_value()}};
  if (!options.smoothing) {
    report["smoothing"]["solidity_ks"] = solid.smoothing.solidityKs;
    report["smoothing"]["roundness_ks"] = solid.smoothing.roundnessKs;
  }
  if (options.sizing == Sizing::Sections) {
    report["volume"]["sizing_predicted_ks"] = sizing.predictedKs;
    const SizingUncertainty& u = sizing.uncertainty;
    report["volume"]["sizing_uncertainty"] = {
        {"bootstraps", u.bootstraps},
        {"size_factor_5_95", {u.sizeFactorLow, u.sizeFactorHigh}},
        {"mean_volume_relative_spread", u.meanVolumeSpread},
        {"volume_cdf_band",
         {{"volumes", u.bandVolumes}, {"cdf", u.bandCdf}, {"cdf_5", u.bandLow}, {"cdf_95", u.bandHigh}}}};
  }
  return report;
}

}  // namespace solidtex
