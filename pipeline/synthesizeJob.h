#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "io/writeVolumeExports.h"
#include "synthesis/synthesizeSolid.h"
#include "validation/continuousQuality.h"

namespace solidtex {

/// `solidtex synthesize`: an exemplar without particles to a continuous solid (.vdb, report, previews).
struct SynthesizeJob {
  std::string exemplar;
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

/// Runs the job, writes the requested files and returns the report.
nlohmann::json runSynthesize(const SynthesizeJob& job);

}  // namespace solidtex
