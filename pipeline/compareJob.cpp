#include "pipeline/compareJob.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>

#include "common/Error.h"
#include "pipeline/comparisonPlot.h"
#include "pipeline/jobSupport.h"
#include "segmentation/imageIO.h"
#include "voxel/vdbIO.h"

namespace solidtex {
namespace {

double scaleOf(const CompareJob& job, const SolidVolume& volume) {
  if (job.voxelsPerPixel > 0) return job.voxelsPerPixel;
  const auto it = volume.metadata.find("voxels_per_pixel");
  if (it == volume.metadata.end())
    throw InputError(job.volume + " has no voxels_per_pixel metadata: give --scale");
  return std::stod(it->second);
}

std::vector<double> particleVolumes(const SolidVolume& volume) {
  std::vector<double> counts;
  for (std::int32_t id : volume.particleId) {
    if (id <= 0) continue;
    if (std::size_t(id) > counts.size()) counts.resize(std::size_t(id), 0);
    counts[std::size_t(id - 1)] += 1;
  }
  counts.erase(std::remove(counts.begin(), counts.end(), 0.0), counts.end());
  return counts;
}

double mean(const std::vector<double>& values) {
  return values.empty() ? 0 : std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
}

// Particle volumes of both solids in photo pixels cubed, so that solids made at any scale compare.
nlohmann::json compareWithTruth(const std::string& truthPath, std::vector<double> volumes, double scale) {
  const SolidVolume truth = readVdb(truthPath);
  if (truth.particleId.empty()) throw InputError(truthPath + " has no particle_id grid: not a particle solid");
  const auto it = truth.metadata.find("voxels_per_pixel");
  const double truthScale = it == truth.metadata.end() ? 1.0 : std::strtod(it->second.c_str(), nullptr);
  if (!(truthScale > 0) || !std::isfinite(truthScale))
    throw InputError(truthPath + " has a voxels_per_pixel that is not a positive number");
  std::vector<double> truthVolumes = particleVolumes(truth);
  for (double& v : truthVolumes) v /= truthScale * truthScale * truthScale;
  for (double& v : volumes) v /= scale * scale * scale;
  const double truthMean = mean(truthVolumes);
  return {{"truth", truthPath},
          {"particles", truthVolumes.size()},
          {"mean_volume", truthMean},
          {"solid_mean_volume", mean(volumes)},
          {"volume_ks", ksStatistic(truthVolumes, volumes)},
          {"volume_wasserstein1_over_mean", truthMean > 0 ? wasserstein1(truthVolumes, volumes) / truthMean : 0.0}};
}

} // namespace

nlohmann::json runCompare(const CompareJob& job) {
  const cv::Mat photo = loadPhoto(job.photo);
  const ExemplarStats stats = analyzeExemplar(photo, job.photo, job.segmentation);
  const SolidVolume volume = readVdb(job.volume);
  if (volume.particleId.empty()) throw InputError(job.volume + " has no particle_id grid: not a particle solid");
  const double scale = scaleOf(job, volume);

  std::vector<double> photoAreas;
  for (const auto& p : stats.particles)
    if (!p.border) photoAreas.push_back(p.area * scale * scale);
  SectionOptions sectionOptions = job.sections;
  sectionOptions.minArea = stats.minArea * scale * scale;
  const SectionStatistics sections = sampleSections(volume.dims, volume.particleId, sectionOptions);
  const std::vector<double> volumes = particleVolumes(volume);
  std::size_t occupied = 0;
  for (std::int32_t id : volume.particleId) occupied += id > 0;

  ComparisonData data{photoAreas, sections.areas, stats.histogram.ratios, tenBinRatios(volumes)};
  const double photoMean = mean(photoAreas);
  nlohmann::json report = {
      {"photo", job.photo},
      {"volume", job.volume},
      {"voxels_per_pixel", scale},
      {"area_fraction", stats.areaFraction},
      {"volume_fraction", double(occupied) / double(volume.dims.count())},
      {"section_area_fraction", sections.areaFraction},
      {"area_histogram", stats.histogram.ratios},
      {"volume_histogram", data.volumeHistogram},
      {"particles", volumes.size()},
      {"photo_particles", photoAreas.size()},
      {"sections", {{"planes", sections.planes}, {"count", sections.areas.size()}, {"mean_area", mean(sections.areas)}}},
      {"photo_mean_area", photoMean},
      {"ks", ksStatistic(photoAreas, sections.areas)},
      {"wasserstein1_over_mean", photoMean > 0 ? wasserstein1(photoAreas, sections.areas) / photoMean : 0.0}};
  if (job.truth) report["truth"] = compareWithTruth(*job.truth, volumes, scale);
  if (job.plot) writeImage(*job.plot, plotComparison(data, report));
  if (job.report) writeJsonFile(*job.report, report);
  return report;
}

} // namespace solidtex
