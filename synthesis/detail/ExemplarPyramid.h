#pragma once
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "synthesis/detail/RgbImage.h"

namespace solidtex::synthesis::detail {

/// An exemplar at every synthesis level, index 0 the coarsest; each level is the next finer one
/// halved (area average), so exemplar pixel p at level l corresponds to 2p + {0,1}^2 at level l+1.
struct ExemplarPyramid {
  std::vector<RgbImage> levels;
  /// Per level, one value per exemplar pixel (row-major) of the control map, or empty when none:
  /// how much more that pixel should appear (brighter = more). Always > 0 where present.
  std::vector<std::vector<float>> control;
};

/// Converts a photo (CV_32FC1/3/4 in [0,1] or CV_8UC1/3/4, channel order R,G,B) to an RgbImage.
/// Throws InputError when empty or of an unsupported type.
RgbImage toRgbImage(const cv::Mat& srgb);

/// Converts a greyscale control map (CV_8U or CV_32F, 1 or 3 channels) to one float in [0,1] per pixel.
/// Throws InputError when empty or of an unsupported type.
std::vector<float> toControlValues(const cv::Mat& control);

/// Halves an image (area average of 2x2 blocks; odd last rows/columns are dropped).
RgbImage halve(const RgbImage& image);

/// Builds `levels` levels from the finest exemplar; the control map (one value per finest pixel) is
/// averaged alongside. Control values are shifted by a small floor so that black still appears a little.
ExemplarPyramid buildExemplarPyramid(const RgbImage& finest, int levels,
                                     const std::vector<float>& control = {});

}  // namespace solidtex::synthesis::detail
