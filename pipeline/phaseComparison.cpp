#include "pipeline/phaseComparison.h"

#include "common/Error.h"
#include "common/distributionDistance.h"
#include "segmentation/particlePhases.h"
#include "validation/compareSections.h"

namespace solidtex {
namespace {

// The solid's phase centres: colours, and grain where the solid was made with it.
cv::Mat phaseCentres(const SolidVolume& volume, const std::string& volumePath) {
  const auto text = volume.metadata.find("phase_lab");
  const nlohmann::json lab =
      text == volume.metadata.end() ? nlohmann::json() : nlohmann::json::parse(text->second, nullptr, false);
  if (!lab.is_array() || lab.size() < 2 || lab.size() > std::size_t(kMaxPhases))
    throw InputError(volumePath +
                     " has a phase grid but no phase colours (phase_lab) to sort the photo's particles by");
  cv::Mat centres(int(lab.size()), 3, CV_32F);
  for (int r = 0; r < centres.rows; ++r) {
    const nlohmann::json& row = lab[std::size_t(r)];
    if (!row.is_array() || row.size() != 3)
      throw InputError(volumePath + ": its phase colours (phase_lab) are damaged");
    for (int c = 0; c < 3; ++c) {
      const nlohmann::json& v = row[std::size_t(c)];
      if (!v.is_number()) throw InputError(volumePath + ": its phase colours (phase_lab) are damaged");
      centres.at<float>(r, c) = v.get<float>();
    }
  }
  const auto grainText = volume.metadata.find("phase_grain");
  if (grainText == volume.metadata.end()) return centres;
  const nlohmann::json grain = nlohmann::json::parse(grainText->second, nullptr, false);
  if (!grain.is_array() || grain.size() != lab.size())
    throw InputError(volumePath + ": its phase grain (phase_grain) is damaged");
  cv::Mat grainColumn(centres.rows, 1, CV_32F);
  for (int r = 0; r < centres.rows; ++r) {
    if (!grain[std::size_t(r)].is_number())
      throw InputError(volumePath + ": its phase grain (phase_grain) is damaged");
    grainColumn.at<float>(r) = grain[std::size_t(r)].get<float>();
  }
  cv::hconcat(centres, grainColumn, centres);
  return centres;
}

}  // namespace

nlohmann::json phaseComparison(const ExemplarStats& photoStats, const SolidVolume& volume,
                               const std::string& volumePath, double scale, const SectionOptions& options,
                               double diameter) {
  if (volume.particlePhase.empty()) return nullptr;
  ExemplarStats stats = photoStats;
  assignPhases(stats, nearestPhases(stats, phaseCentres(volume, volumePath)));
  const std::vector<double> areaFractions = phaseAreaFractions(stats);
  nlohmann::json out = nlohmann::json::array();
  for (int k = 0; k < stats.phaseCentres.rows; ++k) {
    const ExemplarStats phase = phaseStats(stats, k);
    std::vector<std::int32_t> ids(volume.particleId.size(), 0);
    std::size_t voxels = 0;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const std::int32_t id = volume.particleId[i];
      if (id > 0 && std::size_t(id) <= volume.particlePhase.size() &&
          volume.particlePhase[std::size_t(id) - 1] == k)
        ids[i] = id, ++voxels;
    }
    const SectionStatistics sections = sampleSections(volume.dims, ids, options);
    std::vector<double> photoAreas;
    for (std::size_t i : statisticalParticles(phase.particles))
      photoAreas.push_back(phase.particles[i].area * scale * scale);
    nlohmann::json entry = {{"phase", k + 1},
                            {"photo_particles", phase.particles.size()},
                            {"area_fraction", areaFractions[std::size_t(k)]},
                            {"volume_fraction", double(voxels) / double(volume.dims.count())},
                            {"section_area_fraction", sections.areaFraction},
                            {"sections", sections.areas.size()}};
    if (!photoAreas.empty() && !sections.areas.empty()) {
      const SectionStatistics photoSections = measureLabelImage(photoLabels(phase, scale), options);
      entry["photo_mean_area"] = mean(photoAreas);
      entry["mean_area"] = mean(sections.areas);
      entry["ks"] = ksStatistic(photoAreas, sections.areas);
      entry["ks_critical_95"] = ksCritical95(photoAreas.size(), sections.areas.size());
      entry["wasserstein1_over_mean"] = wasserstein1(photoAreas, sections.areas) / mean(photoAreas);
      const SectionComparison shapes = compareSections(photoSections, sections, diameter);
      entry["solidity_ks"] = shapes.solidityKs;
      entry["roundness_ks"] = shapes.roundnessKs;
      entry["aspect_ks"] = shapes.aspectKs;
    }
    out.push_back(std::move(entry));
  }
  return out;
}

}  // namespace solidtex
