#include <iostream>
#include <memory>
#include <vector>

#include "cli/commands.h"
#include "cli/optionChecks.h"
#include "common/ThreadLimit.h"
#include "parallel/Communicator.h"
#include "particles/fitBodyForm.h"
#include "particles/fitHullSmoothing.h"
#include "pipeline/particleSolidJob.h"

namespace solidtex::cli {

Action addParticlesCommand(CLI::App& app, const std::string& commandLine) {
  auto job = std::make_shared<ParticleSolidJob>();
  job->commandLine = commandLine;
  auto size = std::make_shared<int>(128);
  auto dims = std::make_shared<std::vector<int>>();
  auto placer = std::make_shared<std::string>("edt");
  auto sizing = std::make_shared<std::string>("sections");
  auto arrangement = std::make_shared<std::string>("uniform");
  auto boundary = std::make_shared<std::string>("open");
  auto matrix = std::make_shared<std::string>("synthesized");
  auto particleTexture = std::make_shared<std::string>("projected");
  CLI::App* command =
      app.add_subcommand("particles", "Make a 3D particle solid (.vdb) from a photo of particles");
  command
      ->add_option("photo", job->photo,
                   "Photo of particles (PNG, JPEG, TIFF, EXR); with --photo-xz or --photo-yz, the xy plane's")
      ->required();
  command->add_option(
      "--photo-xz", job->photoXz,
      "A material that differs by direction: the photo of its xz plane (x across, z down); the "
      "particles are aligned with the axes. Alone, it stands for the yz plane too");
  command->add_option("--photo-yz", job->photoYz,
                      "The photo of the yz plane (y across, z down); alone, it stands for the xz plane too");
  command
      ->add_option("--pixel-sizes", job->pixelSizes,
                   "The side of a pixel of the xy, xz and yz photos (one unit): the xz and yz photos are "
                   "resampled to the xy photo's (default: one size for all)")
      ->expected(3);
  command->add_flag("--pixel-sizes-from-files", job->pixelSizesFromFiles,
                    "Take the three photos' pixel sizes from their resolution metadata (TIFF, PNG pHYs, "
                    "JPEG density) instead");
  command->add_option("-o,--output", job->output, "Output volume (.vdb)")->required();
  auto* sizeOption =
      command->add_option("--size", *size, "Edge of the cubic volume in voxels")->capture_default_str();
  command->add_option("--dims", *dims, "Volume edges X Y Z in voxels (instead of --size)")
      ->expected(3)
      ->excludes(sizeOption);
  command
      ->add_option(
          "--scale", job->voxelsPerPixel,
          "Voxels per photo pixel (default: 1, less when particles would exceed a quarter of the volume)")
      ->check(aboveAtMost(0, 64));
  command->add_option("--placer", *placer, "Spaciousness field: " + placerNames())->capture_default_str();
  command
      ->add_option("--sizing", *sizing,
                   "sections: particle sizes whose random sections match the photo's areas; bbox: the "
                   "paper's, from 2D boxes")
      ->capture_default_str();
  command
      ->add_option("--arrangement", *arrangement,
                   "uniform: each particle at a random spot that holds it, scattered as in most photos; "
                   "best-fit: the paper's, the tightest spot")
      ->capture_default_str();
  auto* boundaryOption =
      command
          ->add_option("--boundary", *boundary,
                       "open: the volume is cut from a larger solid, particles run through its faces; "
                       "walls: the paper's, particles stay inside; periodic: a 3D torus whose copies tile")
          ->capture_default_str();
  command
      ->add_flag_callback(
          "--periodic", [boundary] { *boundary = "periodic"; },
          "The volume tiles without seams: particles leaving by a face come back by the opposite one "
          "(--boundary periodic)")
      ->excludes(boundaryOption);
  command
      ->add_option("--matrix", *matrix,
                   "The background between the particles: synthesized (a solid texture grown from the "
                   "photo's background, its particles filled) or projected (the paper's)")
      ->capture_default_str();
  command
      ->add_option(
          "--particle-texture", *particleTexture,
          "The particles' insides: projected (the paper's: each one's own pixels, projected along one "
          "direction) or synthesized (its shading projected, its grain from a solid texture grown "
          "from the photo's particles: no stripes)")
      ->capture_default_str();
  command->add_option("--views", job->particles.views, "Contours per visual hull (3-5)")
      ->capture_default_str();
  auto smoothing = std::make_shared<std::string>("auto");
  command
      ->add_option(
          "--smoothing", *smoothing,
          "Rounding of the hulls' edges as a share of a particle's size, 0 (the paper's sharp hulls) "
          "to 0.5, or auto: as round as the photo's particles")
      ->capture_default_str();
  auto bodyForm = std::make_shared<std::string>("0");
  command
      ->add_option(
          "--body-form", *bodyForm,
          "Each particle box's middle side moved this share of the way to its longest (1: discs) or, "
          "negative, to its shortest (-1: rods); 0 keeps the paper's boxes; auto: sections as "
          "elongated as the photo's particles (flattened grains)")
      ->capture_default_str();
  command->add_option("--shapes", job->particles.shapes, "Distinct hull shapes built and reused (1-4096)")
      ->capture_default_str();
  command->add_option(
      "--bricks", job->brickEdge,
      "Place particles brick by brick, in bricks of this edge (at least twice the largest "
      "particle's reach), each with its neighbours' particles as obstacles; mpirun's processes share "
      "the bricks");
  command->add_option("--seed", job->seed, "Random seed: same seed, same volume")->capture_default_str();
  auto threads = std::make_shared<int>(0);
  command->add_option("--threads", *threads, "Worker threads (0 = all cores)");
  command->add_option("--report", job->report, "Write a JSON report");
  command->add_option("--preview", job->preview,
                      "Folder for preview PNGs (middle and oblique slices beside the photo)");
  addExportOptions(*command, job->exports);
  command->add_option(
      "--meshes", job->meshPath,
      "The particles' surfaces: OUT.ply (vertex colours, particle ids) or OUT.obj (+ OUT.mtl, "
      "an object per particle)");
  command->add_flag("!--quiet", job->progress,
                    "No progress line (and, on large volumes, no timing of the placement on a small block "
                    "first for its time left)");
  addSegmentationOptions(*command, job->segmentation);
  addPhaseOptions(*command, job->phases);
  return [job, size, dims, placer, sizing, arrangement, boundary, matrix, particleTexture, smoothing,
          bodyForm, threads] {
    job->dims = dims->empty() ? Dims{*size, *size, *size} : Dims{(*dims)[0], (*dims)[1], (*dims)[2]};
    job->placer = parsePlacerKind(*placer);
    job->sizing = parseSizing(*sizing);
    job->arrangement = parseArrangement(*arrangement);
    job->boundary = parseBoundary(*boundary);
    job->matrix = parseTexture("--matrix", *matrix);
    job->particleTexture = parseTexture("--particle-texture", *particleTexture);
    job->smoothing = parseSmoothing(*smoothing);
    job->bodyForm = parseBodyForm(*bodyForm);
    const ThreadLimit limit(threadsPerProcess(*threads));
    const auto report = runParticleSolid(*job);
    if (launchedAs().rank != 0) return 0;
    const auto& volume = report["volume"];
    const bool planes = volume.contains("target_fraction");
    std::cout << job->output << ": " << volume["particles"] << " particles, volume fraction "
              << volume["volume_fraction"].get<double>() << (planes ? " (three photos' mean " : " (photo ")
              << volume[planes ? "target_fraction" : "area_fraction"].get<double>() << "), "
              << volume["stop_reason"].get<std::string>() << '\n';
    return 0;
  };
}

}  // namespace solidtex::cli
