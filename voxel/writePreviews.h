#pragma once
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "common/OutputFiles.h"
#include "common/SolidVolume.h"

namespace solidtex {

/// Writes PNGs a person can look at into `dir`, a folder declared in `outputs`: the three middle axis slices
/// (`slice_x.png`, `slice_y.png`, `slice_z.png`), one oblique slice through the centre with normal
/// (1,2,3) (`slice_oblique.png`), and `preview.png` with the photo and the four slices side by side.
/// `photoSrgb` is CV_32FC3 sRGB. Returns the paths written.
std::vector<std::string> writePreviews(OutputFiles& outputs, const std::string& dir, const cv::Mat& photoSrgb,
                                       const SolidVolume& volume);

}  // namespace solidtex
