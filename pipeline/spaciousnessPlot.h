#pragma once
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace solidtex {

/// One spaciousness field's signed errors (field minus exact, voxels): at the free voxels, or for
/// Delaunay at its circumcentre candidates.
struct FieldErrors {
  std::string name;
  std::vector<double> errors;
  double seconds = 0;
};
using SpaciousnessErrors = std::vector<FieldErrors>;

/// One histogram panel per field, side by side, on a shared error axis, with mean |error|, max
/// and build time printed: an sRGB CV_32FC3 image for writeImage.
cv::Mat plotSpaciousnessErrors(const SpaciousnessErrors& fields);

}  // namespace solidtex
