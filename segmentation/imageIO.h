#pragma once
#include <string>

#include <opencv2/core.hpp>

namespace solidtex {

/// Largest width or height loadPhoto accepts; larger headers are refused before decoding.
inline constexpr int kMaxPhotoSide = 20000;
/// Smallest width or height loadPhoto accepts: below it there is nothing to segment.
inline constexpr int kMinPhotoSide = 8;

/// Loads any image OpenImageIO reads (PNG, JPEG, TIFF, EXR; 8/16-bit/float; grey/RGB/RGBA) as
/// CV_32FC3 sRGB in [0,1], R,G,B order (alpha is dropped; float images tagged linear are encoded
/// to sRGB; values are clamped to [0,1]). Throws InputError, naming the file and the problem,
/// for a missing or unreadable file, a truncated image, or a size outside
/// [kMinPhotoSide, kMaxPhotoSide] (checked on the header, before any pixel is decoded).
cv::Mat loadPhoto(const std::string& path);

/// Writes a CV_32FC3 sRGB [0,1] or CV_8UC3 image (R,G,B order), or a one-channel CV_32F [0,1] /
/// CV_8U grey image, as an 8-bit PNG. Writes to a temporary name beside `path` and renames, so no
/// partial file is left. Throws InputError when the file cannot be written.
void writeImage(const std::string& path, const cv::Mat& srgb);

}  // namespace solidtex
