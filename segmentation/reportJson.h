#pragma once
#include <nlohmann/json.hpp>

#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// The segmentation as JSON for the report (no residual pixels): `image` {width, height, name},
/// `particle_count`, `particles` [{id, area, width, height, x, y, color [r,g,b] linear, border}],
/// `area_fraction`, `background_color` [r,g,b] linear, `min_area`, `histogram` {edges, counts,
/// ratios} and `size_pairs` [{width, height, count}].
nlohmann::json toJson(const ExemplarStats& stats);

/// Phase colours (K x 3 CV_32F, CIE L*a*b*, as ExemplarStats::phaseCentres) as [[L, a, b], ...]: the
/// report's and the `.vdb`'s `phase_lab`.
nlohmann::json phaseColoursJson(const cv::Mat& centres);

}  // namespace solidtex
