#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/optionChecks.h"
#include "pipeline/analyzeJob.h"

namespace solidtex::cli {

Action addAnalyzeCommand(CLI::App& app) {
  auto job = std::make_shared<AnalyzeJob>();
  CLI::App* command = app.add_subcommand("analyze", "Segment a photo of particles and measure them");
  command->add_option("photo", job->photo, "Photo of particles (PNG, JPEG, TIFF, EXR)")->required();
  addSegmentationOptions(*command, job->segmentation);
  addPhaseOptions(*command, job->phases);
  command->add_option("--seed", job->seed, "Random seed of the phases' k-means")->capture_default_str();
  command->add_option("--report", job->report, "Write the statistics as JSON");
  command->add_option("--labels", job->labels, "Write the photo with particle outlines and ids (PNG)");
  return [job] {
    const auto report = runAnalyze(*job);
    std::cout << job->photo << ": " << report["particle_count"] << " particles, area fraction "
              << report["area_fraction"].get<double>();
    if (report.contains("phases")) std::cout << ", " << report["phases"].size() << " phases";
    std::cout << '\n';
    return 0;
  };
}

}  // namespace solidtex::cli
