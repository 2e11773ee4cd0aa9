#pragma once
#include <array>
#include <optional>
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
/// [kMinPhotoSide, kMaxPhotoSide] or more memory than is available (photoMemoryBytes; both checked
/// on the header, before any pixel is decoded). What the codec libraries print on stderr is kept
/// off the terminal: it goes into the error's message, or nowhere when the image reads.
cv::Mat loadPhoto(const std::string& path);

/// The width and height of a pixel of the image at `path`, in metres, from its resolution metadata
/// (TIFF X/YResolution, PNG pHYs, JPEG density: OpenImageIO's XResolution, YResolution and
/// ResolutionUnit in inches, centimetres, millimetres or metres); none when it gives no unit or
/// no positive resolution.
std::optional<std::array<double, 2>> pixelSizeOf(const std::string& path);

/// The pixel types a photo in memory may have.
enum class PixelType { UInt8, Float32 };

/// A photo held in memory (`height` rows of `width` pixels of `channels` values each: 1 grey,
/// 3 RGB, 4 RGBA; row-major, no padding), as loadPhoto reads the same pixels from a file: 8-bit
/// values are converted as OpenImageIO converts them, floats are taken as sRGB and clamped to
/// [0,1], grey is repeated, alpha dropped. `name` labels it in messages; throws InputError for a
/// size or channel count loadPhoto would refuse.
cv::Mat photoFromPixels(const void* pixels, PixelType type, int width, int height, int channels,
                        const std::string& name);

/// Bytes that loading and analysing (analyzeExemplar) a width x height photo take at their peak;
/// loadPhoto refuses, before decoding, a photo whose estimate exceeds availableMemoryBytes().
double photoMemoryBytes(int width, int height);

/// Writes a CV_32FC3 sRGB [0,1] or CV_8UC3 image (R,G,B order), or a one-channel CV_32F [0,1] /
/// CV_8U grey image, as an 8-bit PNG, checking every write. Throws InputError when the file cannot
/// be written (commands write through OutputFiles).
void writeImage(const std::string& path, const cv::Mat& srgb);

}  // namespace solidtex
