#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "segmentation/analyzeExemplar.h"
#include "segmentation/particlePhases.h"

namespace solidtex {

/// `solidtex analyze`: segment a photo and measure its particles.
struct AnalyzeJob {
  std::string photo;
  SegmentationOptions segmentation;
  PhaseOptions phases;                ///< kinds of particle, sorted by colour and grain or by a label image
  std::uint64_t seed = 1;             ///< the k-means' seed
  std::optional<std::string> report;  ///< JSON report path
  std::optional<std::string> labels;  ///< PNG with outlines and ids
};

/// Runs the job, writes the requested files and returns the report.
nlohmann::json runAnalyze(const AnalyzeJob& job);

}  // namespace solidtex
