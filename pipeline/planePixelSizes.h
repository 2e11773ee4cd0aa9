#pragma once
/// @file planePixelSizes.h
/// @brief The photos of a material's three planes brought to one pixel size.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace solidtex {

/// A pixel's width and height, in one unit for all the photos compared.
using PixelSize = std::array<double, 2>;

/// The pixel sizes of the xy, xz and yz photos: `given` (one square size per photo, as
/// `--pixel-sizes` takes them), else with `fromFiles` each file's resolution metadata
/// (pixelSizeOf); none otherwise (the photos are taken to share one). Opt-in, as cameras and
/// editors write 72 or 96 dpi that say nothing of the subject. Throws OptionError for a given size
/// that is not positive or not three of them, InputError when a file gives no size (naming it).
std::optional<std::array<PixelSize, 3>> planePixelSizes(const std::vector<double>& given,
                                                        const std::array<std::string, 3>& paths,
                                                        bool fromFiles);

/// `photo` (of `name`, whose pixels are `size`) resampled so that its pixels are `target` wide and
/// high: area averaging where it shrinks, linear where it grows; the photo itself when they are
/// already. Throws InputError when the ratio lies outside [1/8, 8] (photos that far apart do not
/// show one material at one resolution) or the result is smaller or larger than a photo may be.
cv::Mat atPixelSize(const cv::Mat& photo, const PixelSize& size, double target, const std::string& name);

/// The xy photo's pixel side, the target of the others: InputError when its pixels are not square
/// (within 1 %), as the solid's voxels are cubes of its pixels.
double squarePixelSide(const PixelSize& xy, const std::string& name);

}  // namespace solidtex
