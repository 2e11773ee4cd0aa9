#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "io/writeVolumeExports.h"
#include "synthesis/growSolid.h"
#include "validation/continuousQuality.h"

namespace solidtex {

/// `solidtex synthesize PHOTO --grow-from N`: a photo's small solid grown brick by brick to a large
/// one (.vdb, report, previews).
struct GrowSolidJob {
  std::string exemplar;  ///< the photo
  std::string output;    ///< .vdb path
  GrowOptions grow;      ///< brickEdge 0: chosen by growBrickEdge
  std::optional<std::string> report;
  std::optional<std::string> preview;  ///< folder for PNGs
  VolumeExports exports;               ///< TIFF stacks, numpy arrays, .vti
  std::string commandLine;
  bool progress = true;              ///< a progress line on stderr
  bool measure = true;               ///< the report's `quality`
  ContinuousQualityOptions quality;  ///< how it is measured
};

/// Photo solids larger than this per side are grown by default: chen-wang takes two minutes at
/// 256^3 and its memory grows with the volume.
inline constexpr int kLargestDirectPhotoSolid = 256;
/// The seed solid's edge when growing is not asked for by --grow-from.
inline constexpr int kDefaultGrowSeed = 128;

/// The seed edge a photo solid is grown from: `growFrom` when given (0: not grown), else
/// kDefaultGrowSeed when the output is given by its dims or is larger than kLargestDirectPhotoSolid
/// per side, else 0.
int growSeedEdge(std::optional<int> growFrom, bool dimsGiven, const Dims& dims);

/// Chooses the brick edge when `options` has none (growBrickEdge) and refuses (InputError) a growth
/// the available memory cannot hold. Returns the estimated peak bytes.
double planGrowthMemory(GrowOptions& options);

/// Estimated peak bytes of growing a solid of `dims` in bricks of `edge` (0: one brick), given the
/// synthesis's correction margin (voxels beyond a brick's faces at the finest level) and the size
/// of the seed solid's analysis.
double growPeakBytes(const Dims& dims, int edge, int margin, const VolumeAnalysisSize& seed);

/// The brick edge a growth uses when none is given: the whole volume when that fits in
/// `availableBytes`, else the largest of 512, 256, 128 and 64 that does (64 when none does).
int growBrickEdge(const Dims& dims, int margin, const VolumeAnalysisSize& seed, double availableBytes);

/// The grown solid's quality against the photo, measured on at most its central 256^3 box.
ContinuousQuality measureGrownSolid(const SolidVolume& volume, const cv::Mat& photoSrgb,
                                    const ContinuousQualityOptions& options);

/// The report of a growth: the seed solid's synthesis, the growth's options, bricks and timings,
/// and the quality when measured (no outputs or memory).
nlohmann::json grownSolidReport(const GrowOptions& options, const GrowResult& result,
                                const ContinuousQuality* quality,
                                const ContinuousQualityOptions& qualityOptions);

/// Runs the job, writes the requested files and returns the report.
nlohmann::json runGrowSolid(const GrowSolidJob& job);

}  // namespace solidtex
