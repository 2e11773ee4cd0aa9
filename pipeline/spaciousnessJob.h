#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/Grid.h"
#include "segmentation/analyzeExemplar.h"

namespace solidtex {

/// `solidtex spaciousness`: the four spaciousness fields against the exact Euclidean value on one
/// scene of the photo's particles.
struct SpaciousnessJob {
  std::string photo;
  SegmentationOptions segmentation;
  int size = 128;     ///< cubic volume edge, voxels
  int particles = 0;  ///< particles placed before the fields are compared; 0: up to the photo's fraction
  std::uint64_t seed = 1;
  bool periodic = false;              ///< the volume is a 3D torus (particles wrap, distances too)
  std::optional<std::string> report;  ///< JSON
  std::optional<std::string> plot;    ///< PNG of the error histograms
  bool progress = true;
};

/// Runs the job, writes the requested files and returns the report.
nlohmann::json runSpaciousness(const SpaciousnessJob& job);

}  // namespace solidtex
