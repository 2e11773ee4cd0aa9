#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "common/SolidVolume.h"

namespace solidtex {

/// What measureContinuousSolid samples and compares.
struct ContinuousQualityOptions {
  int similaritySide = 8;                    ///< patch side of coherence and completeness
  std::vector<int> distanceSides{4, 8, 16};  ///< patch sides of the patch distribution distance
  std::vector<int> scales{
      1, 2};  ///< each patch pixel the mean of scale x scale samples: 2 sees coarser structure
  /// Patches per set, the same for slices and images (fewer if an image holds fewer): every patch of
  /// a 128^2 exemplar, a sample of larger ones.
  int patches = 16384;
  int queries = 1024;          ///< of them, how many look for their nearest patch in the other set
  int directions = 64;         ///< random projections of the sliced Wasserstein distance
  int histogramBins = 8;       ///< per channel, joint colour histograms
  std::uint64_t seed = 12345;  ///< where the patches lie
  /// Axis slices orthogonal to this axis only (0: yz, 1: xz, 2: xy), for a material that differs by
  /// direction, each plane against its own photo; -1: all three. Oblique planes take every orientation.
  int planeAxis = -1;
};

/// The patch distribution distance at one patch side and scale.
struct PatchDistance {
  int side = 0;
  int scale = 0;
  int patches = 0;      ///< per set
  double distance = 0;  ///< sliced Wasserstein-1, sRGB units
};

/// How a set of patches (slices of the solid, or a second photo) compares with the exemplar's patches.
/// Distances are RMS per component, sRGB in [0,1]; each figure is the mean over the scales.
struct PatchSimilarity {
  double coherence = 0;      ///< mean distance of a patch to its nearest exemplar patch
  double completeness = 0;   ///< mean distance of an exemplar patch to its nearest patch of the set
  double patchDistance = 0;  ///< mean of patchDistances
  std::vector<PatchDistance> patchDistances;

  /// Simakov et al.'s bidirectional similarity (as a distance: lower is closer).
  double bidirectional() const { return coherence + completeness; }
};

/// Statistics of the position histogram (voxels per exemplar pixel).
struct PositionHistogramStats {
  double coverage = 0;   ///< share of exemplar pixels copied by at least one voxel
  double flatness = 0;   ///< normalised entropy of the histogram: 1 = every pixel equally often
  double variation = 0;  ///< coefficient of variation (std / mean) of the counts
};

/// A continuous solid's slices against its exemplar, and a second photo's patches against the same
/// exemplar as the reference level.
struct ContinuousQuality {
  PatchSimilarity axis;     ///< slices orthogonal to x, y and z
  PatchSimilarity oblique;  ///< randomly rotated planes
  std::optional<PatchSimilarity> reference;
  double colorHistogramDistance = 0;  ///< the solid's voxels against the exemplar's pixels
  std::optional<double> referenceColorHistogramDistance;
  std::optional<PositionHistogramStats>
      positions;  ///< when the solid records the exemplar pixel each voxel copies
  double seconds = 0;
};

/// Measures a continuous solid against its exemplar (CV_32FC3 sRGB, as loadPhoto returns) and, when
/// `reference` is not empty, a second photo of the material against the same exemplar with the
/// same number of patches. Patches lie wholly inside the solid; a patch size or scale that does not
/// fit in the solid or in an image is left out. Deterministic for any thread count. Throws
/// InputError when no similarity patch fits.
ContinuousQuality measureContinuousSolid(const SolidVolume& solid, const cv::Mat& exemplar,
                                         const cv::Mat& reference = {},
                                         const ContinuousQualityOptions& options = {});

/// A 2D texture against its exemplar, and a second photo against the same exemplar.
struct TextureQuality {
  PatchSimilarity texture;
  std::optional<PatchSimilarity> reference;
  double colorHistogramDistance = 0;
  std::optional<double> referenceColorHistogramDistance;
  double seconds = 0;
};

/// Measures a synthesised 2D texture (CV_32FC3 sRGB) against its exemplar as measureContinuousSolid
/// measures a solid's slices, with the same reference level.
TextureQuality measureTexture(const cv::Mat& texture, const cv::Mat& exemplar, const cv::Mat& reference = {},
                              const ContinuousQualityOptions& options = {});

/// Total-variation distance (in [0,1]) between the joint RGB histograms (bins^3) of two sets of
/// interleaved sRGB colours.
double colorHistogramDistance(const float* a, std::size_t countA, const float* b, std::size_t countB,
                              int bins = 8);

/// Statistics of the sources (exemplar pixel index per voxel, negative = none) over `pixels` pixels.
PositionHistogramStats positionHistogramStats(const std::vector<std::int32_t>& sources, int pixels);

}  // namespace solidtex
