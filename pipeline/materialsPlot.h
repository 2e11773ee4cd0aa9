#pragma once
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

namespace solidtex {

/// The materials descriptors' curves of the particle phase (else the report's first phase), the photo's
/// beside the sections' and the solid's: S2, lineal path, chord-length histogram and local thickness, four
/// panels `width` wide in all (CV_32FC3, white ground), from the report's "materials" (materialsReport).
cv::Mat plotMaterials(const nlohmann::json& materials, int width);

}  // namespace solidtex
