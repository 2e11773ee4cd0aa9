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
};
using SpaciousnessErrors = std::vector<FieldErrors>;

/// One histogram panel per field, side by side, on a shared error axis, with mean |error| and max
/// printed (times are the report's: the plot is the same bytes on every run): an sRGB CV_32FC3
/// image for writeImage.
cv::Mat plotSpaciousnessErrors(const SpaciousnessErrors& fields);

}  // namespace solidtex
