#include "segmentation/reportJson.h"

#include "segmentation/particlePhases.h"

namespace solidtex {
namespace {

nlohmann::json rgb(const cv::Vec3f& c) { return nlohmann::json::array({c[0], c[1], c[2]}); }

nlohmann::json particleJson(const Particle2D& p) {
  return {{"id", p.id},   {"area", p.area}, {"width", p.box.width},  {"height", p.box.height},
          {"x", p.box.x}, {"y", p.box.y},   {"color", rgb(p.color)}, {"border", p.border}};
}

nlohmann::json histogramJson(const AreaHistogram& h) {
  return {{"edges", h.edges}, {"counts", h.counts}, {"ratios", h.ratios}};
}

// Each phase's colour, particles, share of the photo and own area histogram.
nlohmann::json phasesJson(const ExemplarStats& stats) {
  const std::vector<double> fractions = phaseAreaFractions(stats);
  const nlohmann::json colours = phaseColoursJson(stats.phaseCentres);
  const nlohmann::json grain = phaseGrainJson(stats.phaseCentres);
  nlohmann::json out = nlohmann::json::array();
  for (int k = 0; k < stats.phaseCentres.rows; ++k) {
    const ExemplarStats phase = phaseStats(stats, k);
    out.push_back({{"phase", k + 1},
                   {"lab", colours[std::size_t(k)]},
                   {"grain", grain.is_null() ? nullptr : grain[std::size_t(k)]},
                   {"particle_count", phase.particles.size()},
                   {"area_fraction", fractions[std::size_t(k)]},
                   {"histogram", histogramJson(phase.histogram)}});
  }
  return out;
}

}  // namespace

nlohmann::json phaseColoursJson(const cv::Mat& centres) {
  nlohmann::json out = nlohmann::json::array();
  for (int r = 0; r < centres.rows; ++r)
    out.push_back({centres.at<float>(r, 0), centres.at<float>(r, 1), centres.at<float>(r, 2)});
  return out;
}

nlohmann::json phaseGrainJson(const cv::Mat& centres) {
  if (centres.cols < 4) return nullptr;
  nlohmann::json out = nlohmann::json::array();
  for (int r = 0; r < centres.rows; ++r) out.push_back(centres.at<float>(r, 3));
  return out;
}

nlohmann::json toJson(const ExemplarStats& stats) {
  const bool phases = stats.phaseCentres.rows > 1;
  nlohmann::json particles = nlohmann::json::array();
  for (const Particle2D& p : stats.particles) {
    particles.push_back(particleJson(p));
    if (phases) particles.back()["phase"] = p.phase + 1;
  }
  nlohmann::json pairs = nlohmann::json::array();
  for (const SizePair& s : stats.sizePairs)
    pairs.push_back({{"width", s.width}, {"height", s.height}, {"count", s.count}});
  nlohmann::json out = {
      {"image", {{"width", stats.imageWidth}, {"height", stats.imageHeight}, {"name", stats.name}}},
      {"particle_count", stats.particles.size()},
      {"particles", std::move(particles)},
      {"area_fraction", stats.areaFraction},
      {"background_color", rgb(stats.backgroundColor)},
      {"outline_blur", stats.outlineBlur},
      {"outlines", stats.halfMaximumOutlines ? "half-maximum" : "watershed"},
      {"min_area", stats.minArea},
      {"regions_below_min_area", stats.regionsBelowMinArea},
      {"area_share_below_min_area", stats.areaShareBelowMinArea},
      {"histogram", histogramJson(stats.histogram)},
      {"size_pairs", std::move(pairs)}};
  if (phases) out["phases"] = phasesJson(stats);
  return out;
}

}  // namespace solidtex
