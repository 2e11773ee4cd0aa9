#pragma once
#include <nlohmann/json.hpp>

#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// The segmentation as JSON for the report (no residual pixels): `image` {width, height, name},
/// `particle_count`, `particles` [{id, area, width, height, x, y, color [r,g,b] linear, border}],
/// `area_fraction`, `background_color` [r,g,b] linear, `min_area`, `histogram` {edges, counts,
/// ratios} and `size_pairs` [{width, height, count}].
nlohmann::json toJson(const ExemplarStats& stats);

/// Phase colours (the first three columns of ExemplarStats::phaseCentres, CIE L*a*b*) as
/// [[L, a, b], ...]: the report's and the `.vdb`'s `phase_lab`.
nlohmann::json phaseColoursJson(const cv::Mat& centres);

/// Phase grain contrasts (the fourth column of ExemplarStats::phaseCentres, L* units) as [g, ...]:
/// the report's and the `.vdb`'s `phase_grain`; null when the centres hold colours alone.
nlohmann::json phaseGrainJson(const cv::Mat& centres);

}  // namespace solidtex
