#include "pipeline/planePixelSizes.h"

#include <cmath>
#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "io/imageIO.h"

namespace solidtex {
namespace {

constexpr double kMaxRatio = 8;
constexpr double kSquareTolerance = 0.01;

std::string metres(const PixelSize& size) {
  char text[64];
  std::snprintf(text, sizeof text, "%.4g x %.4g m", size[0], size[1]);
  return text;
}

}  // namespace

std::optional<std::array<PixelSize, 3>> planePixelSizes(const std::vector<double>& given,
                                                        const std::array<std::string, 3>& paths,
                                                        bool fromFiles) {
  if (!given.empty()) {
    if (given.size() != 3) throw OptionError("--pixel-sizes takes three sizes: the xy, xz and yz photos'");
    std::array<PixelSize, 3> out;
    for (std::size_t i = 0; i < 3; ++i) {
      if (!(given[i] > 0) || !std::isfinite(given[i]))
        throw OptionError("--pixel-sizes must be positive, got " + std::to_string(given[i]));
      out[i] = {given[i], given[i]};
    }
    return out;
  }
  if (!fromFiles) return std::nullopt;
  std::array<std::optional<PixelSize>, 3> found;
  for (std::size_t i = 0; i < 3; ++i) found[i] = pixelSizeOf(paths[i]);
  const int known = int(found[0].has_value()) + int(found[1].has_value()) + int(found[2].has_value());
  if (known == 0)
    throw InputError("none of the three photos gives a pixel size: give --pixel-sizes XY XZ YZ");
  if (known < 3) {
    std::string with, without;
    for (std::size_t i = 0; i < 3; ++i) {
      std::string& list = found[i] ? with : without;
      list += (list.empty() ? "" : ", ") + paths[i];
    }
    throw InputError(with + (known == 1 ? " gives" : " give") + " a pixel size and " + without +
                     " none: give --pixel-sizes XY XZ YZ");
  }
  return std::array<PixelSize, 3>{*found[0], *found[1], *found[2]};
}

double squarePixelSide(const PixelSize& xy, const std::string& name) {
  if (std::abs(xy[0] - xy[1]) > kSquareTolerance * std::max(xy[0], xy[1]))
    throw InputError(name + " has pixels of " + metres(xy) + ": the xy photo's pixels must be square");
  return xy[0];
}

cv::Mat atPixelSize(const cv::Mat& photo, const PixelSize& size, double target, const std::string& name) {
  const double fx = size[0] / target, fy = size[1] / target;
  if (fx == 1 && fy == 1) return photo;
  for (const double f : {fx, fy})
    if (!(f >= 1 / kMaxRatio && f <= kMaxRatio))
      throw InputError(name + "'s pixels are " + std::to_string(f) +
                       " times the xy photo's: photos of scales this far apart cannot be reconciled");
  const cv::Size resized(int(std::lround(photo.cols * fx)), int(std::lround(photo.rows * fy)));
  if (resized.width < kMinPhotoSide || resized.height < kMinPhotoSide || resized.width > kMaxPhotoSide ||
      resized.height > kMaxPhotoSide)
    throw InputError(name + " at the xy photo's pixel size would be " + std::to_string(resized.width) + "x" +
                     std::to_string(resized.height) + " pixels, outside what a photo may be");
  cv::Mat out;
  cv::resize(photo, out, resized, 0, 0, fx * fy < 1 ? cv::INTER_AREA : cv::INTER_LINEAR);
  return out;
}

}  // namespace solidtex
