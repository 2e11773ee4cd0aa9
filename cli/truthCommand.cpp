#include <iostream>
#include <memory>
#include <vector>

#include "cli/commands.h"
#include "pipeline/truthJob.h"

namespace solidtex::cli {

Action addTruthCommand(CLI::App& app) {
  auto job = std::make_shared<TruthJob>();
  auto dims = std::make_shared<std::vector<int>>(std::vector<int>{640, 640, 72});
  EllipsoidTruthOptions& t = job->truth;
  CLI::App* command = app.add_subcommand(
      "truth", "Make a test photo with a known 3D truth: random non-overlapping ellipsoids, small ones orange, "
               "large ones blue, and their middle section as the photo");
  command->add_option("-o,--output", job->folder, "Folder for photo.png, truth.vdb and truth.json")->required();
  command->add_option("--dims", *dims, "Volume edges X Y Z in voxels (periodic; the photo is X x Y)")
      ->expected(3)->capture_default_str();
  command->add_option("--fraction", t.volumeFraction, "Volume fraction of the ellipsoids")->capture_default_str();
  command->add_option("--small-radius", t.classes[0].meanRadius, "Median radius of the small class, voxels")
      ->capture_default_str();
  command->add_option("--large-radius", t.classes[1].meanRadius, "Median radius of the large class, voxels")
      ->capture_default_str();
  command->add_option("--large-share", t.classes[1].share, "Share of large particles by number (0-1)")
      ->capture_default_str()->check(CLI::Range(0.0, 1.0));
  auto spread = std::make_shared<double>(t.classes[0].radiusSpread);
  command->add_option("--spread", *spread, "Standard deviation of log radius (both classes)")->capture_default_str();
  command->add_option("--elongation", t.elongation, "Largest axis stretch of an ellipsoid (1 = spheres)")
      ->capture_default_str();
  command->add_option("--noise", t.noise, "Pixel noise of the photo (sRGB standard deviation)")->capture_default_str();
  command->add_option("--seed", t.seed, "Random seed: same seed, same truth")->capture_default_str();
  return [job, dims, spread] {
    EllipsoidTruthOptions& t = job->truth;
    t.dims = {(*dims)[0], (*dims)[1], (*dims)[2]};
    t.classes[0].radiusSpread = t.classes[1].radiusSpread = *spread;
    t.classes[0].share = 1 - t.classes[1].share;
    std::erase_if(t.classes, [](const EllipsoidClass& c) { return c.share <= 0; });
    const auto report = runTruth(*job);
    std::cout << job->folder << ": " << report["particles"] << " ellipsoids, volume fraction "
              << report["volume_fraction"].get<double>() << ", photo area fraction "
              << report["photo_area_fraction"].get<double>() << '\n';
    return 0;
  };
}

} // namespace solidtex::cli
