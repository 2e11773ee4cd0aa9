#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "common/SolidVolume.h"

namespace solidtex {

/// A photo's colours in K classes: the phases of a material with more than two, or of one without
/// particles, for the materials descriptors.
struct ColourClasses {
  cv::Mat centres;  ///< K x 3 CV_32F, CIE L*a*b* (D65), darkest first
  cv::Mat labels;   ///< CV_32S, the photo's class per pixel, 0..K-1
};

/// k-means (OpenCV, k-means++ seeded from `seed`, 3 attempts) of a photo's pixels (CV_32FC3 sRGB,
/// as loadPhoto gives) in CIE L*a*b*. Throws OptionError unless 2 <= classes <= 8.
ColourClasses colourClasses(const cv::Mat& photo, int classes, std::uint64_t seed);

/// The classes a label image of the photo gives: one per distinct colour (8 bits a channel), in
/// increasing order of its packed RGB value (grey levels: darkest first); each centre the mean
/// L*a*b* of the photo's pixels in the class. `labelImage` is CV_32FC3 in [0, 1] (loadPhoto's
/// form). Throws InputError, naming `name`, unless it is the photo's size with 2 to 8 values.
ColourClasses colourClassesOfLabels(const cv::Mat& photo, const cv::Mat& labelImage, const std::string& name);

/// The nearest class (in L*a*b*) of each linear-RGB colour.
std::vector<std::uint8_t> nearestClasses(const std::vector<Rgb>& linear, const cv::Mat& centres);

}  // namespace solidtex
