#pragma once
#include <cstdint>
#include <vector>

#include "synthesis/detail/RgbImage.h"

namespace solidtex::synthesis::detail {

/// The detail coefficients of one Haar level, per coarse pixel and channel (width * height * 3 each).
/// With the averaging normalisation, the 2x2 block p00 p10 / p01 p11 (x right, y down) has the
/// approximation a = (p00 + p10 + p01 + p11) / 4, which is `halve`, and the details
/// h = (p00 - p10 + p01 - p11) / 4 (left minus right), v = (p00 + p10 - p01 - p11) / 4 (top minus bottom)
/// and d = (p00 - p10 - p01 + p11) / 4.
struct HaarDetails {
  int width = 0, height = 0;
  std::vector<float> h, v, d;
};

/// One level of the transform: an image of even size to its approximation and details.
struct HaarLevel {
  RgbImage approximation;
  HaarDetails details;
};

/// Pan et al.'s wavelet pyramid of an exemplar: `coarse` is the skeleton (the exemplar halved
/// `levels` times), details[0] the finest level's coefficients, details[levels - 1] the coarsest.
struct HaarPyramid {
  RgbImage finest;  ///< the exemplar cropped to a multiple of 2^levels
  std::vector<HaarDetails> details;
  RgbImage coarse;
};

/// The forward transform of an image whose width and height are even.
HaarLevel haarForward(const RgbImage& image);

/// The inverse transform: exact (up to float rounding) on haarForward's output.
RgbImage haarInverse(const RgbImage& approximation, const HaarDetails& details);

/// The exemplar's pyramid over `levels` levels (>= 1); the last rows and columns beyond a multiple of
/// 2^levels are cropped.
HaarPyramid buildHaarPyramid(const RgbImage& exemplar, int levels);

/// Algorithm 1's reconstruction: an image at the coarse level whose pixels record the coarse exemplar
/// pixel they come from (index y * coarse.width + x), rebuilt to the finest level. At each level a
/// pixel becomes a 2x2 block, the inverse transform of its own colour and its source's detail
/// coefficients, and the block's pixels come from the source's four children.
RgbImage rebuildFromSources(const RgbImage& image, const std::vector<std::int32_t>& sources,
                            const HaarPyramid& pyramid);

}  // namespace solidtex::synthesis::detail
