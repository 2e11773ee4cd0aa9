#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "synthesis/synthesizeTexture.h"
#include "validation/continuousQuality.h"

namespace solidtex {

/// `solidtex synthesize2d`: an exemplar to a periodic 2D texture (PNG) and its report.
struct SynthesizeTextureJob {
  std::string exemplar;
  std::string output;  ///< .png path
  TextureSynthesisOptions synthesis;
  std::optional<std::string> report;
  std::optional<std::string> reference;  ///< a second photo of the material: the quality's reference level
  bool progress = true;
  bool measure = true;               ///< the report's `quality`
  ContinuousQualityOptions quality;  ///< how it is measured
};

/// Runs the job, writes the requested files and returns the report.
nlohmann::json runSynthesizeTexture(const SynthesizeTextureJob& job);

}  // namespace solidtex
