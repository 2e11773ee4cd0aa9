#pragma once
#include <nlohmann/json.hpp>

#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// The segmentation as JSON for the report (no residual pixels): `image` {width, height, name},
/// `particle_count`, `particles` [{id, area, width, height, x, y, color [r,g,b] linear, border}],
/// `area_fraction`, `background_color` [r,g,b] linear, `min_area`, `histogram` {edges, counts,
/// ratios} and `size_pairs` [{width, height, count}].
nlohmann::json toJson(const ExemplarStats& stats);

}  // namespace solidtex
