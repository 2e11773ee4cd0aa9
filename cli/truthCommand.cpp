#include <iostream>
#include <memory>
#include <vector>

#include "cli/commands.h"
#include "cli/optionChecks.h"
#include "common/Error.h"
#include "pipeline/truthJob.h"

namespace solidtex::cli {

Action addTruthCommand(CLI::App& app) {
  auto job = std::make_shared<TruthJob>();
  auto dims = std::make_shared<std::vector<int>>(std::vector<int>{640, 640, 72});
  ParticleTruthOptions& t = job->truth;
  CLI::App* command = app.add_subcommand(
      "truth",
      "Make a test photo with a known 3D truth: random non-overlapping particles (ellipsoids, "
      "superellipsoids or polytopes), small ones orange, large ones blue, and their middle section as the "
      "photo (photo.png: the xy plane; photo_xz.png and photo_yz.png: the others, z down)");
  command
      ->add_option("-o,--output", job->folder,
                   "Folder for photo.png, photo_xz.png, photo_yz.png, truth.vdb and truth.json")
      ->required();
  command->add_option("--dims", *dims, "Volume edges X Y Z in voxels (periodic; the photo is X x Y)")
      ->expected(3)
      ->capture_default_str();
  auto shape = std::make_shared<std::string>("ellipsoid");
  command
      ->add_option("--shape", *shape,
                   "Particle shape: ellipsoid, superellipsoid or polytope (convex, 12-16 vertices)")
      ->capture_default_str();
  command->add_option("--fraction", t.volumeFraction, "Volume fraction of the particles")
      ->capture_default_str();
  command->add_option("--small-radius", t.classes[0].meanRadius, "Median radius of the small class, voxels")
      ->capture_default_str();
  command->add_option("--large-radius", t.classes[1].meanRadius, "Median radius of the large class, voxels")
      ->capture_default_str();
  command->add_option("--large-share", t.classes[1].share, "Share of large particles by number (0-1)")
      ->check(between(0, 1))
      ->capture_default_str();
  auto medium = std::make_shared<ParticleClass>(ParticleClass{10, 0.2, 0, {0.35f, 0.75f, 0.30f}});
  command
      ->add_option("--medium-share", medium->share,
                   "Share by number of a third, green class between the two (0 = none), taken from the small")
      ->check(between(0, 1))
      ->capture_default_str();
  command->add_option("--medium-radius", medium->meanRadius, "Median radius of the medium class, voxels")
      ->capture_default_str();
  auto mediumSrgb = std::make_shared<std::vector<float>>();
  command
      ->add_option("--medium-srgb", *mediumSrgb,
                   "Colour of the medium class, sRGB in [0, 1] (default green; the small class's 0.92 0.55 "
                   "0.16 with --medium-grain makes a class told apart by its grain alone)")
      ->expected(3)
      ->check(between(0, 1))
      ->needs("--medium-share");
  command
      ->add_option("--medium-grain", medium->grain,
                   "Speckle of the medium class: each pixel's sRGB value varies by this relative standard "
                   "deviation (0 = plain)")
      ->check(between(0, 1))
      ->needs("--medium-share")
      ->capture_default_str();
  auto spread = std::make_shared<double>(t.classes[0].radiusSpread);
  command->add_option("--spread", *spread, "Standard deviation of log radius (both classes, 0-1)")
      ->check(between(0, 1))
      ->capture_default_str();
  command->add_option("--elongation", t.elongation, "Largest axis stretch of a particle (1 = no stretch)")
      ->capture_default_str();
  command
      ->add_option("--flatten", t.flatten,
                   "Ratio of the smallest axis to the others, volume kept (1 = none; 0.5 = oblate 2:1)")
      ->capture_default_str();
  command
      ->add_option("--anisotropy", t.anisotropy,
                   "Aligned particles: their x, y, z semi-axes in these proportions (e.g. 3 1.5 1; volume "
                   "kept), not turned at random")
      ->expected(3);
  command->add_option("--exponent", t.exponent, "Superellipsoid exponent p (2 = ellipsoid; larger = boxier)")
      ->capture_default_str();
  command
      ->add_option("--blur", t.blur,
                   "Gaussian blur of the photo, standard deviation in pixels, before the noise")
      ->capture_default_str();
  command->add_option("--noise", t.noise, "Pixel noise of the photo (sRGB standard deviation)")
      ->capture_default_str();
  command->add_option("--seed", t.seed, "Random seed: same seed, same truth")->capture_default_str();
  return [job, dims, spread, shape, medium, mediumSrgb] {
    ParticleTruthOptions& t = job->truth;
    t.shape = parseTruthShape(*shape);
    t.dims = {(*dims)[0], (*dims)[1], (*dims)[2]};
    t.classes[0].radiusSpread = t.classes[1].radiusSpread = medium->radiusSpread = *spread;
    if (!mediumSrgb->empty()) medium->srgb = {(*mediumSrgb)[0], (*mediumSrgb)[1], (*mediumSrgb)[2]};
    // Shares that add up to 1 in decimals leave the small class a rounding error, not a share.
    constexpr double kRounding = 1e-9;
    t.classes[0].share = 1 - t.classes[1].share - medium->share;
    if (t.classes[0].share < -kRounding)
      throw OptionError("--large-share and --medium-share must add up to at most 1");
    if (t.classes[0].share < kRounding) t.classes[0].share = 0;
    t.classes.insert(t.classes.begin() + 1, *medium);
    std::erase_if(t.classes, [](const ParticleClass& c) { return c.share <= 0; });
    const auto report = runTruth(*job);
    std::cout << job->folder << ": " << report["particles"] << ' ' << *shape << "s, volume fraction "
              << report["volume_fraction"].get<double>() << ", photo area fraction "
              << report["photo_area_fraction"].get<double>() << '\n';
    return 0;
  };
}

}  // namespace solidtex::cli
