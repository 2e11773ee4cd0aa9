#include "pipeline/truthJob.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "common/Error.h"
#include "common/memoryBudget.h"
#include "common/srgb.h"
#include "io/imageIO.h"
#include "io/vdbIO.h"
#include "pipeline/jobOutputs.h"
#include "segmentation/analyzeExemplar.h"
#include "segmentation/particlePhases.h"
#include "segmentation/particleShading.h"
#include "segmentation/reportJson.h"

namespace solidtex {
namespace {

// The particle share of the middle section across `plane` (the axis it holds fixed).
double sectionAreaFraction(const SolidVolume& volume, int plane) {
  const Dims& d = volume.dims;
  const int edges[3] = {d.x, d.y, d.z};
  const int a = plane == 0 ? 1 : 0, b = plane == 2 ? 1 : 2;
  std::size_t filled = 0;
  int at[3];
  at[plane] = edges[plane] / 2;
  for (at[b] = 0; at[b] < edges[b]; ++at[b])
    for (at[a] = 0; at[a] < edges[a]; ++at[a]) filled += volume.particleId[d.index(at[0], at[1], at[2])] > 0;
  return double(filled) / (double(edges[a]) * double(edges[b]));
}

nlohmann::json optionsJson(const ParticleTruthOptions& options) {
  nlohmann::json classes = nlohmann::json::array();
  for (const ParticleClass& c : options.classes)
    classes.push_back({{"median_radius", c.meanRadius},
                       {"spread", c.radiusSpread},
                       {"share", c.share},
                       {"srgb", {c.srgb[0], c.srgb[1], c.srgb[2]}},
                       {"grain", c.grain}});
  return {{"volume_fraction", options.volumeFraction},
          {"classes", classes},
          {"elongation", options.elongation},
          {"flatten", options.flatten},
          {"exponent", options.exponent},
          {"blur", options.blur},
          {"noise", options.noise},
          {"anisotropy",
           options.anisotropy.empty() ? nlohmann::json(nullptr) : nlohmann::json(options.anisotropy)}};
}

// The classes' colours in CIE L*a*b*, as a particle solid's `phase_lab` metadata holds its phases'.
nlohmann::json classColoursJson(const std::vector<ParticleClass>& classes) {
  std::vector<cv::Vec3f> linear;
  for (const ParticleClass& c : classes)
    linear.emplace_back(srgbToLinear(c.srgb[0]), srgbToLinear(c.srgb[1]), srgbToLinear(c.srgb[2]));
  return phaseColoursJson(labOfColours(linear));
}

// Each class's grain as the photo shows it: the mean grain contrast of the photo's particles of the
// class (the class of the truth particle under most of each). Classes that differ by grain alone
// share one `phase_lab` colour; with this `phase_grain`, as with a solid's, `compare` tells them apart.
nlohmann::json classGrainJson(const ParticleTruth& truth, std::size_t classes) {
  const ExemplarStats stats = analyzeExemplar(truth.photo, "photo.png", {});
  const Dims& d = truth.volume.dims;
  std::vector<double> sums(classes, 0.0);
  std::vector<int> counts(classes, 0);
  for (const Particle2D& p : stats.particles) {
    const double grain = grainContrast(p);
    if (std::isnan(grain)) continue;
    std::map<std::int32_t, int> votes;
    for (int y = 0; y < p.box.height; ++y)
      for (int x = 0; x < p.box.width; ++x)
        if (p.mask.at<std::uint8_t>(y, x))
          ++votes[truth.volume.particleId[d.index(p.box.x + x, p.box.y + y, d.z / 2)]];
    const std::int32_t id = std::max_element(votes.begin(), votes.end(), [](const auto& a, const auto& b) {
                              return a.second < b.second;
                            })->first;
    if (id == 0) continue;
    const auto c = std::size_t(truth.classOf[std::size_t(id - 1)]);
    sums[c] += grain;
    ++counts[c];
  }
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t c = 0; c < classes; ++c) out.push_back(counts[c] > 0 ? sums[c] / counts[c] : 0.0);
  return out;
}

}  // namespace

// Peak resident memory per voxel: 30 measured (367 MiB at 256x256x128, less the 130 MiB every run holds).
constexpr double kTruthBytesPerVoxel = 32;

nlohmann::json runTruth(const TruthJob& job) {
  requireVolumeMemory("the truth", job.truth.dims, kTruthBytesPerVoxel);
  OutputFiles outputs;
  outputs.addFolder("-o", job.folder);
  ParticleTruth truth = makeParticleTruth(job.truth);

  std::vector<int> perClass(job.truth.classes.size(), 0);
  std::vector<double> classFractions(job.truth.classes.size(), 0.0);
  for (std::size_t i = 0; i < truth.classOf.size(); ++i) {
    ++perClass[std::size_t(truth.classOf[i])];
    classFractions[std::size_t(truth.classOf[i])] += truth.volumes[i] / double(truth.volume.dims.count());
  }
  // The classes are the truth's phases, as a particle solid's are: `compare` rates each one.
  if (job.truth.classes.size() > 1) {
    truth.volume.particlePhase.assign(truth.classOf.begin(), truth.classOf.end());
    truth.volume.metadata["phase_lab"] = classColoursJson(job.truth.classes).dump();
    if (std::any_of(job.truth.classes.begin(), job.truth.classes.end(),
                    [](const ParticleClass& c) { return c.grain > 0; }))
      truth.volume.metadata["phase_grain"] = classGrainJson(truth, job.truth.classes.size()).dump();
  }
  nlohmann::json report = {
      {"dims", {truth.volume.dims.x, truth.volume.dims.y, truth.volume.dims.z}},
      {"seed", job.truth.seed},
      {"shape", truthShapeName(job.truth.shape)},
      {"options", optionsJson(job.truth)},
      {"particles", truth.classOf.size()},
      {"particles_per_class", perClass},
      {"volume_fraction_per_class", classFractions},
      {"volume_fraction", truth.volumeFraction},
      {"photo_area_fraction", sectionAreaFraction(truth.volume, 2)},
      {"photo_xz_area_fraction", sectionAreaFraction(truth.volume, 1)},
      {"photo_yz_area_fraction", sectionAreaFraction(truth.volume, 0)},
      {"volumes", truth.volumes},
  };
  const std::filesystem::path folder(job.folder);
  outputs.write((folder / "photo.png").string(),
                [&](const std::string& path) { writeImage(path, truth.photo); });
  outputs.write((folder / "photo_xz.png").string(),
                [&](const std::string& path) { writeImage(path, truth.photoXz); });
  outputs.write((folder / "photo_yz.png").string(),
                [&](const std::string& path) { writeImage(path, truth.photoYz); });
  truth.volume.metadata["exemplar"] = "photo.png";
  truth.volume.metadata["seed"] = std::to_string(job.truth.seed);
  outputs.write((folder / "truth.vdb").string(),
                [&](const std::string& path) { writeVdb(path, std::move(truth.volume)); });
  outputs.write((folder / "truth.json").string(),
                [&](const std::string& path) { writeJsonFile(path, report); });
  outputs.commit();
  return report;
}

}  // namespace solidtex
