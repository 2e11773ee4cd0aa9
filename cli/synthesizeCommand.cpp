#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "common/Error.h"
#include "parallel/Communicator.h"
#include "pipeline/growSolidJob.h"
#include "pipeline/synthesizeJob.h"
#include "pipeline/synthesizeVolumeJob.h"

namespace solidtex::cli {

void addPyramidOptions(CLI::App& command, int& levels, int& waveletLevels, std::vector<int>& neighborhoods,
                       std::string& distance) {
  command.add_option("--levels", levels, "Multi-resolution levels (1-8)")->capture_default_str();
  command
      .add_option("--wavelet-levels", waveletLevels,
                  "skeletal: finest levels rebuilt from Haar details instead of optimised (below --levels)")
      ->capture_default_str();
  command.add_option("--neighborhoods", neighborhoods, "Neighbourhood side per level, coarsest first")
      ->delimiter(',')
      ->capture_default_str();
  command
      .add_option(
          "--distance", distance,
          "Neighbourhood distance: rgb (colours) or wavelet (Haar coefficients of each pixel's 2x2 block)")
      ->capture_default_str();
}

namespace {

// Options that only one kind of exemplar uses; the other kind refuses them when given.
struct ExemplarKindOptions {
  std::vector<CLI::Option*> photoOnly, volumeOnly;
};

void refuseOptionsOf(const std::vector<CLI::Option*>& options, const std::string& kind) {
  for (const CLI::Option* option : options)
    if (option->count() > 0)
      throw OptionError(option->get_name() + " applies to " + kind + " exemplars only");
}

// Volume exemplars (Su 2008): the options only they have, written into `job`.
void addVolumeOptions(CLI::App& command, SynthesizeVolumeJob& job, std::vector<int>& dims,
                      std::vector<int>& region, ExemplarKindOptions& kinds) {
  VolumeSynthesisOptions& v = job.synthesis;
  kinds.volumeOnly = {
      command.add_option("--dims", dims, "Volume exemplars: output voxels X Y Z (instead of --size)")
          ->expected(3),
      command.add_option(
          "--field", job.field,
          "Volume exemplars: steer the exemplar's axes by circle, oval, slant, zigzag, slant3d or a "
          ".vdb with Vec3s grids axis_x, axis_y, axis_z"),
      command.add_option("--jitter", v.jitter, "Volume exemplars: jitter strength r per level (0-2)")
          ->capture_default_str(),
      command
          .add_option("--exclusion", v.exclusion,
                      "Volume exemplars: similarity set members keep this cube apart")
          ->capture_default_str(),
      command
          .add_option("--appearance", v.window,
                      "Volume exemplars: side of the appearance neighbourhoods (odd)")
          ->capture_default_str(),
      command.add_option("--corrections", v.corrections, "Volume exemplars: correction passes per level")
          ->capture_default_str(),
      command
          .add_option(
              "--region", region,
              "Volume exemplars: write only the box X0 Y0 Z0 X1 Y1 Z1 (voxels [X0,X1) ...), identical "
              "to that box of the whole volume")
          ->expected(6)};
}

// What the volume job wrote, for its line on stdout.
std::string volumeOutputSummary(const SynthesizeVolumeJob& job) {
  const auto sides = [](const Dims& d) {
    return std::to_string(d.x) + "x" + std::to_string(d.y) + "x" + std::to_string(d.z);
  };
  const Dims& d = job.synthesis.dims;
  if (job.synthesis.region)
    return "the " + sides(job.synthesis.region->dims()) + " box of a " + sides(d) +
           " volume from a volume exemplar";
  std::string line = sides(d) + " voxels from a volume exemplar";
  if (job.brickEdge > 0) line += ", in bricks of " + std::to_string(job.brickEdge);
  const int processes = launchedAs().size;
  if (processes > 1) line += " on " + std::to_string(processes) + " processes";
  return line;
}

// A photo solid grown to a large volume: the seed's photo options, the growth's volume options.
std::shared_ptr<GrowSolidJob> growJobOf(const SynthesizeJob& photo, const SynthesizeVolumeJob& volume,
                                        int seedEdge, int brickEdge) {
  auto grow = std::make_shared<GrowSolidJob>();
  grow->exemplar = photo.exemplar;
  grow->output = photo.output;
  grow->grow.seed = photo.synthesis;
  grow->grow.seed.size = seedEdge;
  grow->grow.volume = volume.synthesis;
  grow->grow.volume.seed = photo.synthesis.seed;
  grow->grow.volume.threads = photo.synthesis.threads;
  grow->grow.brickEdge = brickEdge;
  grow->report = photo.report;
  grow->preview = photo.preview;
  grow->exports = photo.exports;
  grow->commandLine = photo.commandLine;
  grow->progress = photo.progress;
  grow->measure = photo.measure;
  return grow;
}

}  // namespace

Action addSynthesizeCommand(CLI::App& app, const std::string& commandLine) {
  auto job = std::make_shared<SynthesizeJob>();
  auto volumeJob = std::make_shared<SynthesizeVolumeJob>();
  job->commandLine = volumeJob->commandLine = commandLine;
  auto method = std::make_shared<std::string>("chen-wang");
  auto distance = std::make_shared<std::string>("rgb");
  auto similaritySearch = std::make_shared<std::string>("auto");
  auto dims = std::make_shared<std::vector<int>>();
  auto region = std::make_shared<std::vector<int>>();
  auto kinds = std::make_shared<ExemplarKindOptions>();
  auto growFrom = std::make_shared<int>(-1);
  auto brickEdge = std::make_shared<int>(0);
  SynthesisOptions& o = job->synthesis;
  CLI::App* command = app.add_subcommand("synthesize",
                                         "Make a continuous solid (.vdb) from an exemplar without particles: "
                                         "a photo (Chen-Wang, Kopf, skeletal) or "
                                         "a volume (.vdb, Su 2008 appearance-space pyramid synthesis)");
  command->add_option("exemplar", job->exemplar, "Exemplar image (PNG, JPEG, TIFF, EXR) or volume (.vdb)")
      ->required();
  command->add_option("-o,--output", job->output, "Output volume (.vdb)")->required();
  command->add_option("--photo-xz", job->photoXz,
                      "Photo exemplars: a material that differs by direction, the exemplar of its xz plane "
                      "(x across, z down; the exemplar is then the xy plane's, one size for all). Alone, it "
                      "stands for the yz plane too");
  command->add_option(
      "--photo-yz", job->photoYz,
      "The exemplar of the yz plane (y across, z down); alone, it stands for the xz plane too");
  command
      ->add_option("--method", *method,
                   "Photo exemplars: chen-wang (histogram matching), kopf (baseline) or skeletal (chen-wang "
                   "on the Haar "
                   "skeleton, finer levels rebuilt from wavelet details)")
      ->capture_default_str();
  command->add_option("--size", o.size, "Edge of the cubic volume in voxels (2-1024)")->capture_default_str();
  addPyramidOptions(*command, o.levels, o.waveletLevels, o.neighborhoods, *distance);
  command->get_option("--levels")
      ->description(
          "Multi-resolution levels (1-8; volume exemplars: corrected levels, default as many as fit)");
  command->add_option("--k", o.k, "k-coherence similarity set size (1-64; volume exemplars: 3)")
      ->capture_default_str();
  command
      ->add_option(
          "--similarity-search", *similaritySearch,
          "Photo exemplars: how similarity sets are found: exact (kd-tree), approximate (FAISS inverted "
          "file, for large exemplars) or auto (approximate from " +
              std::to_string(o.approximateFrom) + " neighbourhoods per level)")
      ->capture_default_str();
  command->add_option("--iterations", o.iterations, "Photo exemplars: iterations per level (1-100)")
      ->capture_default_str();
  command
      ->add_option("--pca-dims", o.pcaDims, "PCA dimensions of neighbourhoods (1-512; volume exemplars: 16)")
      ->capture_default_str();
  command->add_option("--control", job->control,
                      "Photo exemplars: greyscale map the exemplar's size: brighter appears more");
  addVolumeOptions(*command, *volumeJob, *dims, *region, *kinds);
  // Both kinds: the photo methods always synthesise on a torus, so for them the flag changes nothing.
  command->add_flag("--periodic", volumeJob->synthesis.periodic,
                    "Make the volume a 3D torus whose copies tile without a seam (photo exemplars always "
                    "are; volume exemplars: each side a multiple of 2^(corrected levels))");
  command
      ->add_option("--grow-from", *growFrom,
                   "Photo exemplars: make an N^3 solid by --method and grow it to --size or --dims by "
                   "volume synthesis, brick by brick (default: " +
                       std::to_string(kDefaultGrowSeed) + " past --size " +
                       std::to_string(kLargestDirectPhotoSolid) + " or with --dims; 0: never)")
      ->check(CLI::Range(0, 256));
  command->add_option("--bricks", *brickEdge,
                      "Volume exemplars and grown solids: synthesise bricks of this edge one at a time (same "
                      "voxels, less memory; grown default: the whole volume when it fits in memory). Volume "
                      "exemplars: an edge dividing every side; mpirun's processes share the bricks");
  for (const char* name :
       {"--method", "--wavelet-levels", "--neighborhoods", "--distance", "--similarity-search",
        "--iterations", "--control", "--grow-from", "--photo-xz", "--photo-yz"})
    kinds->photoOnly.push_back(command->get_option(name));
  command->add_option("--seed", o.seed, "Random seed: same seed, same volume")->capture_default_str();
  command->add_option("--threads", o.threads, "Worker threads (0 = all cores)");
  command->add_option("--report", job->report, "Write a JSON report");
  command->add_option("--preview", job->preview, "Folder for preview PNGs");
  addExportOptions(*command, job->exports);
  command->add_flag("!--quiet", job->progress, "No progress line");
  command->add_flag("!--no-quality", job->measure,
                    "Do not measure the result against the exemplar (the report's quality)");
  return [job, volumeJob, method, distance, similaritySearch, dims, region, kinds, growFrom, brickEdge,
          command] {
    const SynthesisOptions& o = job->synthesis;  // as parsed
    if (std::filesystem::path(job->exemplar).extension() == ".vdb") {
      refuseOptionsOf(kinds->photoOnly, "photo");
      SynthesizeVolumeJob& v = *volumeJob;
      v.exemplar = job->exemplar;
      v.output = job->output;
      v.synthesis.dims =
          dims->empty() ? Dims{o.size, o.size, o.size} : Dims{(*dims)[0], (*dims)[1], (*dims)[2]};
      if (!region->empty())
        v.synthesis.region =
            Box{{(*region)[0], (*region)[1], (*region)[2]}, {(*region)[3], (*region)[4], (*region)[5]}};
      if (command->get_option("--levels")->count() > 0) v.synthesis.levels = o.levels;
      if (command->get_option("--k")->count() > 0) v.synthesis.k = o.k;
      if (command->get_option("--pca-dims")->count() > 0) v.synthesis.pcaDims = o.pcaDims;
      v.synthesis.seed = o.seed;
      v.synthesis.threads = o.threads;
      v.report = job->report;
      v.preview = job->preview;
      v.exports = job->exports;
      v.progress = job->progress;
      v.measure = job->measure;
      v.brickEdge = *brickEdge;
      if (*brickEdge == 0 && command->get_option("--bricks")->count() > 0)
        throw OptionError("--bricks must be positive, got 0");
      runSynthesizeVolume(v);
      if (launchedAs().rank == 0) std::cout << v.output << ": " << volumeOutputSummary(v) << '\n';
      return 0;
    }
    requireOneProcess("synthesize from a photo");
    job->synthesis.method = parseMethod(*method);
    job->synthesis.distance = parseDistance(*distance);
    job->synthesis.similaritySearch = parseSimilaritySearch(*similaritySearch);
    const Dims out = dims->empty() ? Dims{o.size, o.size, o.size} : Dims{(*dims)[0], (*dims)[1], (*dims)[2]};
    const int seedEdge =
        growSeedEdge(*growFrom >= 0 ? std::optional<int>(*growFrom) : std::nullopt, !dims->empty(), out);
    if (seedEdge > 0) {
      refuseOptionsOf({command->get_option("--region"), command->get_option("--field")}, "volume (.vdb)");
      if (job->photoXz || job->photoYz)
        throw OptionError("--photo-xz and --photo-yz make solids up to --size " +
                          std::to_string(kLargestDirectPhotoSolid) + ", not grown ones");
      SynthesizeVolumeJob& v = *volumeJob;
      v.synthesis.dims = out;
      if (*brickEdge < 0) throw OptionError("--bricks must be positive, got " + std::to_string(*brickEdge));
      const auto growJob = growJobOf(*job, v, seedEdge, *brickEdge);
      runGrowSolid(*growJob);
      std::cout << job->output << ": " << out.x << "x" << out.y << "x" << out.z << " voxels grown from a "
                << seedEdge << "^3 " << *method << " solid\n";
      return 0;
    }
    refuseOptionsOf(kinds->volumeOnly, "volume (.vdb)");
    if (command->get_option("--bricks")->count() > 0)
      throw OptionError("--bricks applies to grown solids only (--grow-from, or --size past " +
                        std::to_string(kLargestDirectPhotoSolid) + ")");
    runSynthesize(*job);
    std::cout << job->output << ": " << job->synthesis.size << "^3 voxels by " << *method << '\n';
    return 0;
  };
}

}  // namespace solidtex::cli
