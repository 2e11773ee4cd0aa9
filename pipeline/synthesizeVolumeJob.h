#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "io/writeVolumeExports.h"
#include "synthesis/synthesizeFromVolume.h"
#include "validation/volumeQuality.h"

namespace solidtex {

/// `solidtex synthesize EXEMPLAR.vdb`: a volume exemplar to a solid (.vdb, report, previews) by Su 2008.
struct SynthesizeVolumeJob {
  std::string exemplar;              ///< .vdb with a `color` (preferred) or `density` grid
  std::string output;                ///< .vdb path
  VolumeSynthesisOptions synthesis;  ///< its field is built from `field`
  std::optional<std::string> field;  ///< a built-in field's name or a .vdb with axis_x, axis_y, axis_z
  std::optional<std::string> report;
  std::optional<std::string> preview;  ///< folder for PNGs
  VolumeExports exports;               ///< TIFF stacks, numpy arrays, .vti
  std::string commandLine;
  bool progress = true;  ///< a progress line on stderr
  bool measure = true;   ///< the report's `quality`
  VolumeQualityOptions quality;
};

/// The exemplar of a volume job: the `color` grid's three channels if the file has one, else `density`.
DenseVolume readVolumeExemplar(const std::string& path);

/// The report of a volume synthesis: the exemplar, the options, each level's statistics and the
/// timings (no quality, outputs or memory).
nlohmann::json volumeSynthesisReport(const VolumeSynthesisResult& result,
                                     const VolumeSynthesisOptions& options, const DenseVolume& exemplar,
                                     const std::string& exemplarName, const std::string& fieldName);

/// The output's 3D patch quality against the exemplar, measured on at most its central 128^3 box;
/// a note instead when it is thinner than a patch.
nlohmann::json volumeQualityReport(const DenseVolume& output, const DenseVolume& exemplar,
                                   const VolumeQualityOptions& options);

/// Runs the job, writes the requested files and returns the report.
nlohmann::json runSynthesizeVolume(const SynthesizeVolumeJob& job);

}  // namespace solidtex
