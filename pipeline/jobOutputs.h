#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/OutputFiles.h"

namespace solidtex {

/// Writes JSON to `path`, checking every write (commands write through OutputFiles).
void writeJsonFile(const std::string& path, const nlohmann::json& json);

/// Declares `--report`, when given, as one of the command's outputs (a .json file).
void addReport(OutputFiles& outputs, const std::optional<std::string>& report);
/// Declares a volume job's outputs: the .vdb, and the report and preview folder when given.
void addVolumeOutputs(OutputFiles& outputs, const std::string& vdb, const std::optional<std::string>& report,
                      const std::optional<std::string>& preview);

/// Writes the report, when asked for, through `outputs`.
void writeReport(OutputFiles& outputs, const std::optional<std::string>& report, const nlohmann::json& json);

}  // namespace solidtex
