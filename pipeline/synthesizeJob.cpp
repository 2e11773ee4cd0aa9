#include "pipeline/synthesizeJob.h"

#include <utility>

#include <filesystem>

#include "common/Error.h"
#include "pipeline/jobSupport.h"
#include "segmentation/imageIO.h"
#include "synthesis/synthesizeSolid.h"
#include "voxel/vdbIO.h"
#include "voxel/writePreviews.h"
#include "Version.h"

namespace solidtex {

nlohmann::json runSynthesize(const SynthesizeJob& job) {
  namespace fs = std::filesystem;
  if (fs::path(job.output).extension() != ".vdb") throw InputError("output " + job.output + " must end in .vdb");
  const fs::path parent = fs::path(job.output).has_parent_path() ? fs::path(job.output).parent_path() : fs::path(".");
  if (!fs::is_directory(parent)) throw InputError("cannot write " + job.output + ": folder " + parent.string() + " does not exist");

  const cv::Mat exemplar = loadPhoto(job.exemplar);
  SynthesisOptions options = job.synthesis;
  options.exemplarName = fs::path(job.exemplar).filename().string();
  if (job.control) options.control = loadPhoto(*job.control);
  ProgressLine progress(job.progress);
  if (job.progress) options.progress = [&](const std::string& line) { progress.update(line); };
  SynthesisResult result = synthesizeSolid(exemplar, options);
  progress.done();

  result.volume.metadata["solidtex_version"] = SOLIDTEX_VERSION;
  result.volume.metadata["command_line"] = job.commandLine;
  result.volume.metadata["seed"] = std::to_string(options.seed);
  result.volume.metadata["exemplar"] = options.exemplarName;
  nlohmann::json report = result.report;
  report["solidtex_version"] = SOLIDTEX_VERSION;
  report["command"] = "synthesize";
  report["outputs"] = {{"vdb", job.output}};
  if (job.preview) report["outputs"]["previews"] = writePreviews(*job.preview, exemplar, result.volume);
  writeVdb(job.output, std::move(result.volume));
  report["peak_memory_mib"] = peakMemoryMiB();
  if (job.report) writeJsonFile(*job.report, report);
  return report;
}

} // namespace solidtex
