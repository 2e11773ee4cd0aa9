#pragma once
/// @file growSolid.h
/// @brief A photo's continuous solid at sizes the photo methods cannot reach: a small solid grown
/// brick by brick by volume-exemplar synthesis.
#include <cstdint>

#include <opencv2/core.hpp>

#include "common/SolidVolume.h"
#include "synthesis/SynthesisOptions.h"
#include "synthesis/synthesizeFromVolume.h"
#include "synthesis/synthesizeSolid.h"

namespace solidtex {

/// Options of growSolid: how the seed solid is made and how it is grown.
struct GrowOptions {
  SynthesisOptions seed;  ///< the photo method making the seed solid; `seed.size` is its edge
  /// The growth (Su 2008) to `volume.dims`; its region and progress are not used. Its seed and
  /// threads apply to both stages.
  VolumeSynthesisOptions volume;
  int brickEdge = 0;  ///< bricks synthesised one at a time (bounded memory); 0 = the whole volume
  /// Three stages, each with its share done: the seed solid's synthesis, its analysis as a volume
  /// exemplar, and the bricks.
  Progress progress;
};

/// What growSolid made and how.
struct GrowResult {
  SolidVolume volume;               ///< volume.dims, linear RGB colour
  SynthesisStatistics seed;         ///< the seed solid's synthesis
  double analysisSeconds = 0;       ///< the seed solid analysed as a volume exemplar
  double growthSeconds = 0;         ///< every brick's synthesis
  std::size_t bricks = 0;           ///< bricks synthesised
  std::uint64_t finestVoxels = 0;   ///< voxels corrected at the finest level: bricks and margins
  std::array<int, 3> seedDomain{};  ///< seed voxels the growth copies from (its border dropped)
};

/// Makes a `seed.size`^3 solid from the photo (CV_32FC3 sRGB, as loadPhoto returns) and grows it to
/// `volume.dims` by volume-exemplar synthesis, brick by brick: only one brick's work is held
/// besides the output's colours. The bytes depend on the options and seed, not on the brick edge
/// or the thread count, and equal synthesising the seed solid and then the volume from it.
/// Throws InputError or OptionError with one line for bad input.
GrowResult growSolid(const cv::Mat& photoSrgb, const GrowOptions& options);

}  // namespace solidtex
