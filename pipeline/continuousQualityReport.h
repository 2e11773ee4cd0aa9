#pragma once
#include <nlohmann/json.hpp>

#include "validation/continuousQuality.h"

namespace solidtex {

/// The report's `quality` of a continuous solid: coherence, completeness, their sum and the patch
/// distance on axis and oblique slices, and with a reference photo its figures and the solid's as
/// ratios to them (1 = as close to the exemplar as the second photo).
nlohmann::json continuousQualityJson(const ContinuousQuality& quality,
                                     const ContinuousQualityOptions& options);

/// The report's `quality` of a 2D texture: the same figures for the texture and the reference.
nlohmann::json textureQualityJson(const TextureQuality& quality, const ContinuousQualityOptions& options);

}  // namespace solidtex
