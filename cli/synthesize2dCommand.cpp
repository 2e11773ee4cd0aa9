#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "pipeline/synthesizeTextureJob.h"

namespace solidtex::cli {

Action addSynthesize2dCommand(CLI::App& app) {
  auto job = std::make_shared<SynthesizeTextureJob>();
  auto method = std::make_shared<std::string>("kwatra");
  auto distance = std::make_shared<std::string>("rgb");
  auto size = std::make_shared<std::vector<int>>(std::vector<int>{128, 128});
  TextureSynthesisOptions& o = job->synthesis;
  CLI::App* command = app.add_subcommand("synthesize2d", "Make a tileable 2D texture (PNG) from an exemplar");
  command->add_option("exemplar", job->exemplar, "Exemplar image (PNG, JPEG, TIFF, EXR)")->required();
  command->add_option("-o,--output", job->output, "Output image (.png)")->required();
  command
      ->add_option("--method", *method,
                   "kwatra (texture optimisation) or skeletal (the optimisation on the Haar skeleton, finer "
                   "levels rebuilt from wavelet details)")
      ->capture_default_str();
  command->add_option("--size", *size, "Width and height in pixels")->expected(2)->capture_default_str();
  addPyramidOptions(*command, o.levels, o.waveletLevels, o.neighborhoods, *distance);
  command->get_option("--neighborhoods")
      ->description(
          "Neighbourhood side per level, coarsest first (default 16,...,12,8, each at most half the "
          "level's exemplar)")
      ->default_str("");
  command->add_option("--iterations", o.iterations, "Iterations per level (1-100)")->capture_default_str();
  command->add_option("--pca-dims", o.pcaDims, "PCA dimensions of neighbourhoods (1-512)")
      ->capture_default_str();
  command->add_option("--seed", o.seed, "Random seed: same seed, same image")->capture_default_str();
  command->add_option("--threads", o.threads, "Worker threads (0 = all cores)");
  command->add_option("--report", job->report, "Write a JSON report");
  command->add_option("--reference", job->reference,
                      "A second photo of the material: the report's quality also as ratios to it");
  command->add_flag("!--quiet", job->progress, "No progress line");
  command->add_flag("!--no-quality", job->measure,
                    "Do not measure the result against the exemplar (the report's quality)");
  return [job, method, size, distance] {
    job->synthesis.method = parseTextureMethod(*method);
    job->synthesis.distance = parseDistance(*distance);
    job->synthesis.width = (*size)[0];
    job->synthesis.height = (*size)[1];
    runSynthesizeTexture(*job);
    std::cout << job->output << ": " << job->synthesis.width << "x" << job->synthesis.height << " by "
              << *method << '\n';
    return 0;
  };
}

}  // namespace solidtex::cli
