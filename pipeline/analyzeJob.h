#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "segmentation/analyzeExemplar.h"

namespace solidtex {

/// `solidtex analyze`: segment a photo and measure its particles.
struct AnalyzeJob {
  std::string photo;
  SegmentationOptions segmentation;
  std::optional<std::string> report;  ///< JSON report path
  std::optional<std::string> labels;  ///< PNG with outlines and ids
};

/// Runs the job, writes the requested files and returns the report.
nlohmann::json runAnalyze(const AnalyzeJob& job);

}  // namespace solidtex
