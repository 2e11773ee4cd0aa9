#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "pipeline/synthesizeJob.h"

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

Action addSynthesizeCommand(CLI::App& app, const std::string& commandLine) {
  auto job = std::make_shared<SynthesizeJob>();
  job->commandLine = commandLine;
  auto method = std::make_shared<std::string>("chen-wang");
  auto distance = std::make_shared<std::string>("rgb");
  auto similaritySearch = std::make_shared<std::string>("auto");
  SynthesisOptions& o = job->synthesis;
  CLI::App* command =
      app.add_subcommand("synthesize", "Make a continuous solid (.vdb) from an exemplar without particles");
  command->add_option("exemplar", job->exemplar, "Exemplar image (PNG, JPEG, TIFF, EXR)")->required();
  command->add_option("-o,--output", job->output, "Output volume (.vdb)")->required();
  command
      ->add_option(
          "--method", *method,
          "chen-wang (histogram matching), kopf (baseline) or skeletal (chen-wang on the Haar skeleton, "
          "finer levels rebuilt from wavelet details)")
      ->capture_default_str();
  command->add_option("--size", o.size, "Edge of the cubic volume in voxels (2-1024)")->capture_default_str();
  addPyramidOptions(*command, o.levels, o.waveletLevels, o.neighborhoods, *distance);
  command->add_option("--k", o.k, "k-coherence similarity set size (1-64)")->capture_default_str();
  command
      ->add_option("--similarity-search", *similaritySearch,
                   "How similarity sets are found: exact (kd-tree), approximate (FAISS inverted file, for "
                   "large exemplars) or auto (approximate from " +
                       std::to_string(o.approximateFrom) + " neighbourhoods per level)")
      ->capture_default_str();
  command->add_option("--iterations", o.iterations, "Iterations per level (1-100)")->capture_default_str();
  command->add_option("--pca-dims", o.pcaDims, "PCA dimensions of neighbourhoods (1-512)")
      ->capture_default_str();
  command->add_option("--control", job->control, "Greyscale map the exemplar's size: brighter appears more")
      ->check(CLI::ExistingFile);
  command->add_option("--seed", o.seed, "Random seed: same seed, same volume")->capture_default_str();
  command->add_option("--threads", o.threads, "Worker threads (0 = all cores)");
  command->add_option("--report", job->report, "Write a JSON report");
  command->add_option("--preview", job->preview, "Folder for preview PNGs");
  command->add_flag("!--quiet", job->progress, "No progress line");
  command->add_flag("!--no-quality", job->measure,
                    "Do not measure the result against the exemplar (the report's quality)");
  return [job, method, distance, similaritySearch] {
    job->synthesis.method = parseMethod(*method);
    job->synthesis.distance = parseDistance(*distance);
    job->synthesis.similaritySearch = parseSimilaritySearch(*similaritySearch);
    runSynthesize(*job);
    std::cout << job->output << ": " << job->synthesis.size << "^3 voxels by " << *method << '\n';
    return 0;
  };
}

}  // namespace solidtex::cli
