#include "pipeline/jobOutputs.h"

#include "common/writeFileBytes.h"

namespace solidtex {

void writeJsonFile(const std::string& path, const nlohmann::json& json) {
  const std::string text = json.dump(2) + '\n';
  writeFileBytes(path, text.data(), text.size());
}

void addReport(OutputFiles& outputs, const std::optional<std::string>& report) {
  if (report) outputs.addFile("--report", *report, {".json"});
}

void addVolumeOutputs(OutputFiles& outputs, const std::string& vdb, const std::optional<std::string>& report,
                      const std::optional<std::string>& preview) {
  outputs.addFile("-o", vdb, {".vdb"});
  addReport(outputs, report);
  if (preview) outputs.addFolder("--preview", *preview);
}

void writeReport(OutputFiles& outputs, const std::optional<std::string>& report, const nlohmann::json& json) {
  if (report) outputs.write(*report, [&](const std::string& path) { writeJsonFile(path, json); });
}

}  // namespace solidtex
