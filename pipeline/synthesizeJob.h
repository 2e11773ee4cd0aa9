#pragma once
#include <array>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "io/writeVolumeExports.h"
#include "synthesis/synthesizeSolid.h"
#include "validation/continuousQuality.h"

namespace solidtex {

/// `solidtex synthesize`: an exemplar without particles to a continuous solid (.vdb, report, previews).
struct SynthesizeJob {
  std::string exemplar;  ///< the xy plane's when photoXz or photoYz is given
  /// A material that differs by direction: the exemplars of its xz and yz planes (x or y across, z
  /// down), one size with `exemplar`; either alone stands for both
  std::optional<std::string> photoXz, photoYz;
  std::string output;                  ///< .vdb path
  SynthesisOptions synthesis;          ///< its control map is loaded from `control`
  std::optional<std::string> control;  ///< greyscale PNG the exemplar's size
  std::optional<std::string> report;
  std::optional<std::string> preview;  ///< folder for PNGs
  VolumeExports exports;               ///< TIFF stacks, numpy arrays, .vti
  std::string commandLine;
  bool progress = true;              ///< a progress line on stderr
  bool measure = true;               ///< the report's `quality`
  ContinuousQualityOptions quality;  ///< how it is measured
};

/// The report's settings and statistics of a synthesis (snake_case keys, as every report), with the
/// solid's quality when measured.
nlohmann::json synthesisReport(const SynthesisOptions& options, const SynthesisStatistics& statistics,
                               const ContinuousQuality* quality = nullptr,
                               const ContinuousQualityOptions& qualityOptions = {});

/// The report's `planes` of a solid made from plane exemplars (yz, xz, xy, as synthesizeSolid takes
/// them): each plane's exemplar name and, when `quality` is given, that plane's slices measured
/// against it (ContinuousQualityOptions::planeAxis).
nlohmann::json planeExemplarsReport(const SolidVolume& volume, const std::array<cv::Mat, 3>& planes,
                                    const std::array<std::string, 3>& names,
                                    const ContinuousQualityOptions* quality);

/// Runs the job, writes the requested files and returns the report.
nlohmann::json runSynthesize(const SynthesizeJob& job);

}  // namespace solidtex
