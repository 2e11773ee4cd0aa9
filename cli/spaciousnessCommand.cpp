#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "common/ThreadLimit.h"
#include "pipeline/spaciousnessJob.h"

namespace solidtex::cli {

Action addSpaciousnessCommand(CLI::App& app) {
  auto job = std::make_shared<SpaciousnessJob>();
  auto threads = std::make_shared<int>(0);
  CLI::App* command = app.add_subcommand(
      "spaciousness",
      "Measure the four spaciousness fields against exact distances on a scene of the photo's particles");
  command->add_option("photo", job->photo, "Photo of particles (PNG, JPEG, TIFF, EXR)")->required();
  command->add_option("--size", job->size, "Edge of the cubic volume in voxels (16-512)")
      ->capture_default_str();
  command
      ->add_option("--particles", job->particles,
                   "Particles placed before the fields are compared (0: up to the photo's area fraction)")
      ->capture_default_str();
  command->add_option("--seed", job->seed, "Random seed")->capture_default_str();
  command->add_flag("--periodic", job->periodic,
                    "The volume is a 3D torus: particles and distances wrap around its faces");
  command->add_option("--threads", *threads, "Worker threads (0 = all cores)");
  command->add_option("--report", job->report, "Write the measurements as JSON");
  command->add_option("--plot", job->plot, "Write the error histograms as a PNG");
  command->add_flag("!--quiet", job->progress, "No progress line");
  addSegmentationOptions(*command, job->segmentation);
  return [job, threads] {
    const ThreadLimit limit(*threads);
    const auto report = runSpaciousness(*job);
    std::printf(
        "%zu particles in %d^3; field: mean |error| at all free voxels, at %zu Delaunay circumcentres, build "
        "time\n",
        report["particles"].get<std::size_t>(), job->size, report["circumcentres"].get<std::size_t>());
    for (const auto& [name, field] : report["fields"].items())
      std::printf("  %-9s %.4f  %.4f  %.2f s\n", name.c_str(),
                  field["all_voxels"]["mean_abs_error"].get<double>(),
                  field["circumcentres"].value("mean_abs_error", 0.0), field["seconds"].get<double>());
    return 0;
  };
}

}  // namespace solidtex::cli
