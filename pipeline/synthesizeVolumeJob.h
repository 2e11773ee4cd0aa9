#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/OutputFiles.h"
#include "common/SolidVolume.h"
#include "io/writeVolumeExports.h"
#include "synthesis/synthesizeFromVolume.h"
#include "validation/volumeQuality.h"

namespace solidtex {

/// `solidtex synthesize EXEMPLAR.vdb`: a volume exemplar to a solid (.vdb, report, previews) by Su 2008.
struct SynthesizeVolumeJob {
  std::string exemplar;              ///< .vdb with a `color` (preferred) or `density` grid
  std::string output;                ///< .vdb path
  VolumeSynthesisOptions synthesis;  ///< its field is built from `field`
  /// Bricks of this edge, made one at a time and shared among the processes mpirun started; 0: the
  /// whole volume at once (one brick when several processes run). Same bytes for any number of
  /// processes; the voxels of the whole volume made at once.
  int brickEdge = 0;
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

/// The job's frame field over its dims: none, a built-in one or a .vdb's.
std::optional<FrameField> loadVolumeField(const SynthesizeVolumeJob& job);

/// A volume synthesis's voxels as a solid at its place (origin): colour (3 channels) or density,
/// and the exemplar voxels copied.
SolidVolume solidOfSynthesis(VolumeSynthesisResult&& result);

/// Preview PNGs of a solid made from a volume (densities as grey levels) beside the exemplar's
/// middle z slice; the paths written.
std::vector<std::string> writeVolumePreviews(OutputFiles& outputs, const std::string& folder,
                                             const DenseVolume& exemplar, const SolidVolume& solid);

/// The .vdb metadata of the job's solid: version, command line, seed and exemplar.
std::map<std::string, std::string> volumeFileMetadata(const SynthesizeVolumeJob& job);

/// Runs the job, writes the requested files and returns the report. With bricks, or under mpirun,
/// runBrickedVolumeSynthesis.
nlohmann::json runSynthesizeVolume(const SynthesizeVolumeJob& job);

/// The job in bricks of `brickEdge`, each process (of those mpirun started) making a contiguous run
/// of them; rank 0 joins their trees and writes every file (previews and quality from the central
/// box of at most kBrickedPreviewSide^3), the others nothing. All or nothing: a process's failure
/// fails the run on rank 0 with its one line. Exports are refused (OptionError). Returns the report
/// on rank 0, an empty object elsewhere.
nlohmann::json runBrickedVolumeSynthesis(const SynthesizeVolumeJob& job);

/// The largest side of the box a bricked run previews and measures.
inline constexpr int kBrickedPreviewSide = 256;

}  // namespace solidtex
