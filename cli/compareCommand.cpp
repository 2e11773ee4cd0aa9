#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "pipeline/compareJob.h"

namespace solidtex::cli {

Action addCompareCommand(CLI::App& app) {
  auto job = std::make_shared<CompareJob>();
  CLI::App* command = app.add_subcommand("compare", "Compare a particle solid's statistics with its photo");
  command->add_option("photo", job->photo, "The photo the solid was made from")->required();
  command->add_option("volume", job->volume, "The particle solid (.vdb)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--scale", job->voxelsPerPixel,
                      "Voxels per photo pixel (default: from the .vdb's metadata)");
  command
      ->add_option("--axis-planes", job->sections.offsetsPerAxis,
                   "Axis-aligned section planes per axis (1-4096)")
      ->capture_default_str();
  command
      ->add_option("--oblique-planes", job->sections.obliquePlanes,
                   "Random oblique section planes (0-100000)")
      ->capture_default_str();
  command->add_option("--seed", job->sections.seed, "Seed for the oblique planes")->capture_default_str();
  command->add_option("--report", job->report, "Write the comparison as JSON");
  command->add_option("--plot", job->plot, "Write the histograms and CDFs as a PNG");
  command
      ->add_option(
          "--truth", job->truth,
          "The 3D truth the photo was cut from (.vdb, as `solidtex truth` writes): compare particle volumes")
      ->check(CLI::ExistingFile);
  addSegmentationOptions(*command, job->segmentation);
  return [job] {
    const auto r = runCompare(*job);
    std::cout << "area fraction " << r["area_fraction"].get<double>() << ", volume fraction "
              << r["volume_fraction"].get<double>() << ", sections "
              << r["section_area_fraction"].get<double>() << "; section areas vs photo: KS "
              << r["ks"].get<double>() << ", W1/mean " << r["wasserstein1_over_mean"].get<double>() << '\n';
    if (r.contains("truth"))
      std::cout << "particle volumes vs truth: KS " << r["truth"]["volume_ks"].get<double>() << ", W1/mean "
                << r["truth"]["volume_wasserstein1_over_mean"].get<double>() << '\n';
    return 0;
  };
}

}  // namespace solidtex::cli
