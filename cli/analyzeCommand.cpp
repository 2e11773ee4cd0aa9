#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/optionChecks.h"
#include "pipeline/analyzeJob.h"
#include "segmentation/imageIO.h"

namespace solidtex::cli {

void addSegmentationOptions(CLI::App& command, SegmentationOptions& options) {
  command.add_option("--mask", options.maskPath,
                     "Mask image (white = particle) used instead of automatic segmentation");
  command.add_flag("--invert", options.invert, "Swap which class the automatic segmentation calls particle");
  command.add_flag("!--no-split", options.split, "Do not split touching particles");
  command
      .add_option("--min-area", options.minArea,
                  "Drop particles smaller than this many pixels (default: the photo's, from its size and the "
                  "sizes of its regions)")
      ->check(between(0, double(kMaxPhotoSide) * kMaxPhotoSide));
}

Action addAnalyzeCommand(CLI::App& app) {
  auto job = std::make_shared<AnalyzeJob>();
  CLI::App* command = app.add_subcommand("analyze", "Segment a photo of particles and measure them");
  command->add_option("photo", job->photo, "Photo of particles (PNG, JPEG, TIFF, EXR)")->required();
  addSegmentationOptions(*command, job->segmentation);
  command->add_option("--report", job->report, "Write the statistics as JSON");
  command->add_option("--labels", job->labels, "Write the photo with particle outlines and ids (PNG)");
  return [job] {
    const auto report = runAnalyze(*job);
    std::cout << job->photo << ": " << report["particle_count"] << " particles, area fraction "
              << report["area_fraction"].get<double>() << '\n';
    return 0;
  };
}

}  // namespace solidtex::cli
