#include "pipeline/continuousQualityReport.h"

namespace solidtex {
namespace {

nlohmann::json similarityJson(const PatchSimilarity& s) {
  nlohmann::json distances = nlohmann::json::array();
  for (const PatchDistance& d : s.patchDistances)
    distances.push_back(
        {{"side", d.side}, {"scale", d.scale}, {"patches", d.patches}, {"distance", d.distance}});
  return {{"coherence", s.coherence},
          {"completeness", s.completeness},
          {"bidirectional_similarity", s.bidirectional()},
          {"patch_distance", s.patchDistance},
          {"patch_distances", distances}};
}

// A figure of the solid over the reference's: null where the reference's is zero (the exemplar itself).
nlohmann::json ratio(double solid, double reference) {
  return reference > 0 ? nlohmann::json(solid / reference) : nlohmann::json(nullptr);
}

nlohmann::json ratiosJson(const PatchSimilarity& s, const PatchSimilarity& reference) {
  return {{"coherence", ratio(s.coherence, reference.coherence)},
          {"completeness", ratio(s.completeness, reference.completeness)},
          {"bidirectional_similarity", ratio(s.bidirectional(), reference.bidirectional())},
          {"patch_distance", ratio(s.patchDistance, reference.patchDistance)}};
}

nlohmann::json header(const ContinuousQualityOptions& o) {
  return {{"distance_units", "RMS per component, sRGB in [0, 1]"},
          {"similarity_patch_side", o.similaritySide},
          {"scales", o.scales}};
}

nlohmann::json referenceJson(const PatchSimilarity& reference, std::optional<double> colorDistance) {
  nlohmann::json out = similarityJson(reference);
  out["color_histogram_distance"] = colorDistance.value_or(0.0);
  return out;
}

}  // namespace

nlohmann::json textureQualityJson(const TextureQuality& q, const ContinuousQualityOptions& o) {
  nlohmann::json report = header(o);
  report.update(
      {{"texture", similarityJson(q.texture)}, {"color_histogram_distance", q.colorHistogramDistance}});
  if (q.reference) {
    report["reference"] = referenceJson(*q.reference, q.referenceColorHistogramDistance);
    report["ratio_to_reference"] = {{"texture", ratiosJson(q.texture, *q.reference)}};
  }
  report["seconds"] = q.seconds;
  return report;
}

nlohmann::json continuousQualityJson(const ContinuousQuality& q, const ContinuousQualityOptions& o) {
  nlohmann::json report = header(o);
  report.update({{"axis", similarityJson(q.axis)},
                 {"oblique", similarityJson(q.oblique)},
                 {"color_histogram_distance", q.colorHistogramDistance}});
  if (q.positions)
    report.update({{"position_coverage", q.positions->coverage},
                   {"position_flatness", q.positions->flatness},
                   {"position_variation", q.positions->variation}});
  if (q.reference) {
    report["reference"] = referenceJson(*q.reference, q.referenceColorHistogramDistance);
    report["ratio_to_reference"] = {{"axis", ratiosJson(q.axis, *q.reference)},
                                    {"oblique", ratiosJson(q.oblique, *q.reference)}};
  }
  report["seconds"] = q.seconds;
  return report;
}

}  // namespace solidtex
