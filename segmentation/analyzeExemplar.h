#pragma once
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// How the automatic separation draws the particles' outlines.
enum class OutlineMethod {
  Auto,         ///< half-maximum when the photo's outlines look blurred (kBlurredOutline), else watershed
  Watershed,    ///< where the floods from the background and the particles meet on the edges
  HalfMaximum,  ///< half-way up each particle's smoothed edge (halfMaximumOutlines)
};

/// "auto" | "watershed" | "half-maximum"; throws OptionError otherwise.
OutlineMethod parseOutlineMethod(const std::string& name);

/// Outline blur (pixels, ExemplarStats::outlineBlur) from which OutlineMethod::Auto draws outlines
/// at half maximum.
inline constexpr double kBlurredOutline = 1.0;

/// How the photo is split into particles and background.
struct SegmentationOptions {
  cv::Mat mask;  ///< CV_8U of the photo's size, non-zero = particle; replaces the automatic separation
  std::optional<std::string> maskPath;  ///< read with maskFromImage when `mask` is empty
  bool invert = false;  ///< swap what the automatic separation (or the mask) calls particle and background
  bool split = true;    ///< split touching particles (distance transform + watershed)
  OutlineMethod outlines = OutlineMethod::Auto;  ///< automatic separation only
  double minArea = -1;  ///< pixels; < 0: max(8, the photo's area / 10000), or for a photo whose
                        ///< particles are mostly smaller, an eighth of its typical particle (>= 4)
};

/// Segments the photo and measures every particle (paper 3.2-3.3, 3.6). Automatic separation:
/// Otsu on the clearest of L*, a*, b*, chroma; the less compact class is the background; then the
/// colour distance from the background (lighting evened out), with edges deciding the unclear
/// pixels. Two other readings compete with it (particles of two tones either side of the matrix;
/// the dark gaps of a many-coloured pile) and win when their particles cover clearly more of the
/// photo in compact bodies. A particle is everything inside its outer outline (holes filled).
/// Deterministic.
/// Throws InputError when no particle is found.
ExemplarStats analyzeExemplar(const cv::Mat& photoSrgb, const std::string& name,
                              const SegmentationOptions& options);

/// A mask drawn as an image (CV_32FC3 sRGB, e.g. from loadPhoto) as CV_8U: 255 where its grey is over
/// one half (white = particle), 0 elsewhere.
cv::Mat maskFromImage(const cv::Mat& imageSrgb);

/// loadPhoto + analyzeExemplar.
ExemplarStats analyzeExemplar(const std::string& path, const SegmentationOptions& options);

}  // namespace solidtex
