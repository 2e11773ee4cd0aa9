#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "segmentation/analyzeExemplar.h"
#include "validation/sectionStatistics.h"

namespace solidtex {

/// `solidtex compare`: how well a particle solid's statistics match its photo.
struct CompareJob {
  std::string photo;
  std::string volume;  ///< .vdb with a particle_id grid
  SegmentationOptions segmentation;
  SectionOptions sections;
  double voxelsPerPixel = 0;          ///< <= 0: read from the .vdb's metadata
  std::optional<std::string> report;  ///< JSON
  std::optional<std::string> plot;    ///< PNG
  std::optional<std::string> truth;   ///< .vdb of the 3D truth the photo was cut from (`solidtex truth`)
};

/// Runs the job, writes the requested files and returns the report.
nlohmann::json runCompare(const CompareJob& job);

}  // namespace solidtex
