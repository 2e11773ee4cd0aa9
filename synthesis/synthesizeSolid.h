#pragma once
#include <opencv2/core.hpp>

#include "synthesis/SynthesisOptions.h"

namespace solidtex {

/// Synthesises a solid texture from a 2D exemplar (CV_32FC3 sRGB in [0,1], R,G,B order, as
/// loadPhoto returns; 8-bit and grey images are accepted too) with the chosen method.
/// Same exemplar, options and seed give the same volume for any thread count.
/// Throws InputError with one line for bad input: an exemplar smaller than a level's neighbourhood,
/// a size the levels cannot reach, a control map of the wrong size, invalid counts.
SynthesisResult synthesizeSolid(const cv::Mat& exemplarSrgb, const SynthesisOptions& options);

} // namespace solidtex
