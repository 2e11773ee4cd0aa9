#include "segmentation/reportJson.h"

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

}  // namespace

nlohmann::json toJson(const ExemplarStats& stats) {
  nlohmann::json particles = nlohmann::json::array();
  for (const Particle2D& p : stats.particles) particles.push_back(particleJson(p));
  nlohmann::json pairs = nlohmann::json::array();
  for (const SizePair& s : stats.sizePairs)
    pairs.push_back({{"width", s.width}, {"height", s.height}, {"count", s.count}});
  return {{"image", {{"width", stats.imageWidth}, {"height", stats.imageHeight}, {"name", stats.name}}},
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
}

}  // namespace solidtex
