#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/SolidVolume.h"
#include "pipeline/materialsReport.h"
#include "segmentation/analyzeExemplar.h"
#include "validation/continuousQuality.h"
#include "validation/sectionStatistics.h"

namespace solidtex {

/// What `solidtex compare` measures.
enum class CompareMode {
  Auto,        ///< particles when the .vdb has a particle_id grid, continuous otherwise
  Particles,   ///< section sizes, shapes and arrangement against the photo's particles
  Continuous,  ///< slice patches against the exemplar's (validation/continuousQuality.h)
};

/// Parses "auto" / "particles" / "continuous"; throws InputError otherwise.
CompareMode parseCompareMode(const std::string& name);

/// `solidtex compare`: how well a solid matches its photo: a particle solid's statistics, or a
/// continuous solid's slices.
struct CompareJob {
  std::string photo;   ///< the photo or exemplar the solid was made from
  std::string volume;  ///< .vdb
  CompareMode mode = CompareMode::Auto;
  SegmentationOptions segmentation;
  SectionOptions sections;
  double voxelsPerPixel = 0;             ///< <= 0: read from the .vdb's metadata
  std::optional<std::string> report;     ///< JSON
  std::optional<std::string> plot;       ///< PNG
  std::optional<std::string> truth;      ///< .vdb of the 3D truth the photo was cut from (`solidtex truth`)
  std::optional<std::string> reference;  ///< continuous: a second photo of the material, the reference level
  ContinuousQualityOptions quality;      ///< continuous: how slices are measured
  int brickEdge = 0;  ///< particles: also measure seams along the faces of bricks of this edge; 0: none
  /// Particles: the materials descriptors of photo, sections and solid (materials.measures is
  /// replaced by `measures` when given).
  MaterialsOptions materials;
  std::optional<MeasureSelection> measures;  ///< none given: all but tortuosity
  /// > 0: the phases are the photo's K colour classes (colourClasses) and the solid's voxels by
  /// their nearest class, for any solid; 0: a particle solid's particles and matrix.
  int phases = 0;
  /// An image of the photo's phases, one per distinct value (colourClassesOfLabels), in place of
  /// the k-means classes; at most `phases` of them when that is given.
  std::optional<std::string> phaseMask;
  bool measuresClasses() const { return phases > 0 || phaseMask.has_value(); }
};

/// The report of brickSeams for a particle id volume: the planes within 4 voxels of the inner faces
/// of bricks of `brickEdge` against the rest, in arrangement windows of `windowSide`.
nlohmann::json brickSeamsReport(const std::vector<std::int32_t>& ids, const Dims& dims, int brickEdge,
                                int windowSide);

/// The comparison itself, on a photo (CV_32FC3 sRGB, as loadPhoto returns), a solid and, for a
/// continuous one, a reference photo (or an empty Mat) in memory; the job's paths only label them
/// in the report, apart from its truth (read from its file). `plot`, when given, receives the
/// comparison plot.
nlohmann::json compareSolid(const CompareJob& job, const cv::Mat& photo, const SolidVolume& volume,
                            const cv::Mat& reference, cv::Mat* plot = nullptr);

/// Reads a solid to compare in `mode`: a particle solid's ids alone (the particle measures use no
/// colour, which would take four times their memory) unless `colour`, every grid of a continuous one.
SolidVolume readSolidToCompare(const std::string& path, CompareMode mode, bool colour = false);

/// Runs the job, writes the requested files and returns the report.
nlohmann::json runCompare(const CompareJob& job);

}  // namespace solidtex
