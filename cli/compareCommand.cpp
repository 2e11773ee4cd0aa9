#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/optionChecks.h"
#include "pipeline/compareJob.h"

namespace solidtex::cli {

namespace {

void printSimilarity(const char* name, const nlohmann::json& s) {
  std::cout << name << ": coherence " << s["coherence"].get<double>() << ", completeness "
            << s["completeness"].get<double>() << ", patch distance " << s["patch_distance"].get<double>()
            << '\n';
}

void printContinuous(const nlohmann::json& q) {
  printSimilarity("axis slices", q["axis"]);
  printSimilarity("oblique slices", q["oblique"]);
  if (!q.contains("reference")) return;
  printSimilarity("reference photo", q["reference"]);
  for (const char* kind : {"axis", "oblique"}) {
    const nlohmann::json& r = q["ratio_to_reference"][kind];
    std::cout << kind << " / reference: bidirectional similarity " << r["bidirectional_similarity"]
              << ", patch distance " << r["patch_distance"] << '\n';
  }
}

void printMaterials(const nlohmann::json& phases) {
  for (const auto& [name, phase] : phases.items()) {
    std::cout << name << ", sections vs photo:";
    const nlohmann::json& d = phase["sections_vs_photo"];
    if (d.contains("s2_rms")) std::cout << " S2 rms " << d["s2_rms"].get<double>();
    if (d.contains("chord_mean_ratio")) std::cout << ", mean chord x" << d["chord_mean_ratio"].get<double>();
    if (d.contains("local_thickness_mean_ratio"))
      std::cout << ", local thickness x" << d["local_thickness_mean_ratio"].get<double>();
    if (phase["solid"].contains("tortuosity"))
      for (const auto& [axis, t] : phase["solid"]["tortuosity"].items())
        std::cout << ", tortuosity " << axis << ' '
                  << (t.contains("factor") ? std::to_string(t["factor"].get<double>()) : "none (no path)");
    std::cout << '\n';
  }
}

}  // namespace

Action addCompareCommand(CLI::App& app) {
  auto job = std::make_shared<CompareJob>();
  auto mode = std::make_shared<std::string>("auto");
  auto measures = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "compare",
      "Compare a solid with its photo: a particle solid's statistics or a continuous solid's slices");
  command->add_option("photo", job->photo, "The photo or exemplar the solid was made from")->required();
  command->add_option("volume", job->volume, "The solid (.vdb)")->required();
  command
      ->add_option("--mode", *mode,
                   "auto (particles when the .vdb has a particle_id grid), particles or continuous")
      ->capture_default_str();
  command->add_option("--reference", job->reference,
                      "Continuous: a second photo of the material; every figure also as a ratio to its own");
  command
      ->add_option("--scale", job->voxelsPerPixel,
                   "Voxels per photo pixel (default: from the .vdb's metadata)")
      ->check(aboveAtMost(0, 64));
  command
      ->add_option("--axis-planes", job->sections.offsetsPerAxis,
                   "Axis-aligned section planes per axis (1-4096)")
      ->capture_default_str();
  command
      ->add_option("--oblique-planes", job->sections.obliquePlanes,
                   "Random oblique section planes (0-100000)")
      ->capture_default_str();
  auto plane = std::make_shared<std::string>();
  command
      ->add_option("--plane", *plane,
                   "The photo is of this plane (xy, xz or yz) of a material that differs by direction: "
                   "particles, cut only its axis sections and no oblique ones (no materials descriptors, "
                   "which average every axis); continuous, take only its slices as the axis slices")
      ->check(CLI::IsMember({"xy", "xz", "yz"}));
  command->add_option("--seed", job->sections.seed, "Seed for the planes and patches")->capture_default_str();
  command->add_option("--report", job->report, "Write the comparison as JSON");
  command->add_option("--plot", job->plot,
                      "Write a PNG: particles, the histograms and CDFs; continuous, the exemplar, the "
                      "reference and two slices side by side");
  command->add_option(
      "--truth", job->truth,
      "The 3D truth the photo was cut from (.vdb, as `solidtex truth` writes): compare particle volumes");
  command
      ->add_option("--bricks", job->brickEdge,
                   "Particles: also compare the planes within 4 voxels of the faces of bricks of this edge "
                   "with the rest (seams of `particles --bricks`; on any solid, for a reference)")
      ->check(CLI::PositiveNumber);
  command->add_option("--measures", *measures,
                      "Particles: materials descriptors of photo, sections and solid, a list of s2, lineal, "
                      "chord, psd, minkowski, tortuosity, or all, or none (default: all but tortuosity)");
  command
      ->add_option("--max-distance", job->materials.maxDistance,
                   "Longest separation of the correlation curves, voxels (default: a quarter of the photo's "
                   "shorter side at the solid's scale)")
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option(
          "--phases", job->phases,
          "Measure the photo's K colour classes (k-means in CIE L*a*b*, 2-8) and the solid's voxels by "
          "their nearest class instead of particles and matrix; continuous solids need it for --measures")
      ->check(CLI::Range(2, 8));
  command->add_option("--phase-mask", job->phaseMask,
                      "An image of the photo's phases, one per distinct value (2-8), in place of --phases' "
                      "k-means; the solid's voxels go to the phase of the nearest mean colour");
  command
      ->add_option("--measure-planes", job->materials.planesPerAxis,
                   "Axis sections per axis that the materials descriptors average")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  addSegmentationOptions(*command, job->segmentation);
  return [job, mode, measures, plane] {
    job->mode = parseCompareMode(*mode);
    if (!plane->empty()) {
      job->sections.planeAxis = planeAxisOf(*plane);
      job->sections.obliquePlanes = 0;
    }
    if (!measures->empty()) job->measures = parseMeasureSelection(*measures);
    job->quality.seed = job->sections.seed;
    const auto r = runCompare(*job);
    if (r["mode"] == "continuous") {
      printContinuous(r["quality"]);
      return 0;
    }
    std::cout << "area fraction " << r["area_fraction"].get<double>() << ", volume fraction "
              << r["volume_fraction"].get<double>() << ", sections "
              << r["section_area_fraction"].get<double>() << "; section areas vs photo: KS "
              << r["ks"].get<double>() << ", W1/mean " << r["wasserstein1_over_mean"].get<double>() << '\n';
    if (r.contains("materials")) printMaterials(r["materials"]["phases"]);
    if (r.contains("truth"))
      std::cout << "particle volumes vs truth: KS " << r["truth"]["volume_ks"].get<double>() << ", W1/mean "
                << r["truth"]["volume_wasserstein1_over_mean"].get<double>() << '\n';
    return 0;
  };
}

}  // namespace solidtex::cli
