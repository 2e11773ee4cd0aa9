#include "pipeline/compareJob.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "common/distributionDistance.h"
#include "io/imageIO.h"
#include "io/vdbIO.h"
#include "pipeline/comparisonPlot.h"
#include "pipeline/continuousQualityReport.h"
#include "pipeline/jobOutputs.h"
#include "pipeline/materialsPlot.h"
#include "pipeline/phaseComparison.h"
#include "placement/wholeParticleVolumes.h"
#include "validation/arrangement.h"
#include "validation/brickSeams.h"
#include "validation/colourClasses.h"
#include "validation/compareSections.h"
#include "validation/particleVolumes.h"
#include "voxel/slice.h"

namespace solidtex {
namespace {

// What the particle measures read of a solid: their ids, not the colour that would take four
// times their memory.
constexpr VdbReadOptions kParticleIdsOnly{false, false, true};

double scaleOf(const CompareJob& job, const SolidVolume& volume) {
  if (job.voxelsPerPixel > 0) return job.voxelsPerPixel;
  const auto it = volume.metadata.find("voxels_per_pixel");
  if (it == volume.metadata.end())
    throw InputError(job.volume + " has no voxels_per_pixel metadata: give --scale");
  return std::stod(it->second);
}

bool cutByFaces(const SolidVolume& volume) {
  const auto boundary = volume.metadata.find("boundary");
  return boundary != volume.metadata.end() && boundary->second == "open";
}

// A solid made with an open boundary is a block of a larger one: its faces cut particles.
std::vector<double> particleVolumesOf(const SolidVolume& volume) {
  return particleVolumes(volume.dims, volume.particleId, cutByFaces(volume));
}

// What the solid's particle volumes are a sample of, as the report names it.
const char* volumeSampleOf(const SolidVolume& volume, bool placed) {
  if (placed) return "placed particles whose centre lies in the block, whole";
  return cutByFaces(volume) ? "whole particles in the block, Miles-Lantuejoul weighted"
                            : "particles of the volume";
}

nlohmann::json summaryJson(const SectionSummary& s) {
  return {{"shapes", s.shapes},
          {"solidity_mean", s.solidity},
          {"roundness_mean", s.roundness},
          {"aspect_mean", s.aspect},
          {"windows", s.windows},
          {"window_spread", s.windowSpread},
          {"neighbours", s.neighbours},
          {"neighbour_distance_mean", s.neighbourDistance}};
}

nlohmann::json comparisonJson(const SectionComparison& c, const char* referenceName) {
  return {{referenceName, summaryJson(c.reference)},
          {"sections", summaryJson(c.solid)},
          {"solidity_ks", c.solidityKs},
          {"roundness_ks", c.roundnessKs},
          {"aspect_ks", c.aspectKs},
          {"orientation_ks", c.orientationKs},
          {"shape_ks_critical_95", c.shapeKsCritical},
          {"window_spread_ratio", c.windowSpreadRatio},
          {"neighbour_distance_ks", c.neighbourKs},
          {"neighbour_distance_ratio", c.neighbourRatio}};
}

double truthScaleOf(const std::string& truthPath, const SolidVolume& truth) {
  const auto it = truth.metadata.find("voxels_per_pixel");
  const double truthScale = it == truth.metadata.end() ? 1.0 : std::strtod(it->second.c_str(), nullptr);
  if (!(truthScale > 0) || !std::isfinite(truthScale))
    throw InputError(truthPath + " has a voxels_per_pixel that is not a positive number");
  return truthScale;
}

// The band of the 3D volume CDF the particles' sizing gave (metadata particle_volume_cdf_band), or
// none for solids without it.
std::optional<VolumeCdfBand> volumeBandOf(const SolidVolume& solid, const std::string& solidPath) {
  const auto text = solid.metadata.find("particle_volume_cdf_band");
  if (text == solid.metadata.end()) return std::nullopt;
  const nlohmann::json band = nlohmann::json::parse(text->second, nullptr, false);
  const auto refuse = [&] {
    return InputError(solidPath + ": metadata particle_volume_cdf_band is not the band particles writes");
  };
  const auto curve = [&](const char* key, double lo, double hi) {
    if (band.is_discarded() || !band.contains(key) || !band[key].is_array()) throw refuse();
    std::vector<double> values;
    for (const nlohmann::json& v : band[key]) {
      if (!v.is_number() || !(v.get<double>() >= lo && v.get<double>() <= hi)) throw refuse();
      values.push_back(v.get<double>());
    }
    return values;
  };
  const double most = std::numeric_limits<double>::max();
  VolumeCdfBand out{curve("volumes", std::numeric_limits<double>::min(), most), curve("cdf_5", 0, 1),
                    curve("cdf_95", 0, 1)};
  if (out.volumes.size() < 2 || out.low.size() != out.volumes.size() ||
      out.high.size() != out.volumes.size() ||
      std::adjacent_find(out.volumes.begin(), out.volumes.end(), std::greater_equal<>()) != out.volumes.end())
    throw refuse();
  return out;
}

// Where the truth's volume CDF lies against the band: the share of the band's volumes at which it
// lies inside, how far outside it goes at most, and whether the band meets the truth's own 90 %
// band everywhere: a truth of n particles knows its CDF only to within the DKW bound
// sqrt(ln(2 / 0.1) / 2n) (0.032 for 1500 particles), which the comparison must allow it.
nlohmann::json bandCoverage(const VolumeCdfBand& band, const std::vector<double>& truthVolumes) {
  const std::vector<double> truth = empiricalCdfAt(truthVolumes, band.volumes);
  const double truthBound =
      std::sqrt(std::log(2 / 0.1) / (2.0 * double(std::max<std::size_t>(1, truthVolumes.size()))));
  std::size_t inside = 0;
  double outside = 0;
  for (std::size_t i = 0; i < band.volumes.size(); ++i) {
    const double gap = std::max({0.0, band.low[i] - truth[i], truth[i] - band.high[i]});
    inside += gap == 0;
    outside = std::max(outside, gap);
  }
  return {{"points", band.volumes.size()},
          {"truth_inside_share", double(inside) / double(band.volumes.size())},
          {"largest_excursion", outside},
          {"truth_dkw_bound_90", truthBound},
          {"meets_truth_band_everywhere", outside <= truthBound}};
}

// The solid's volumes against the truth's, both in photo pixels cubed.
nlohmann::json volumeDistances(const std::vector<double>& truthVolumes, const std::vector<double>& volumes) {
  const double truthMean = mean(truthVolumes);
  return {{"solid_mean_volume", mean(volumes)},
          {"volume_ks", ksStatistic(truthVolumes, volumes)},
          {"volume_wasserstein1_over_mean",
           truthMean > 0 ? wasserstein1(truthVolumes, volumes) / truthMean : 0.0}};
}

// Particle volumes of both solids in photo pixels cubed, so that solids made at any scale compare;
// the truth's sections are cut at the solid's resolution so that their shapes compare too.
nlohmann::json compareWithTruth(const std::string& truthPath, std::vector<double> volumes,
                                std::vector<double> blockVolumes, const std::optional<VolumeCdfBand>& band,
                                double scale, const SectionStatistics& solidSections,
                                SectionOptions sectionOptions, double diameter,
                                std::vector<double>& truthOut) {
  const SolidVolume truth = readVdb(truthPath, kParticleIdsOnly);
  if (truth.particleId.empty())
    throw InputError(truthPath + " has no particle_id grid: not a particle solid");
  const double truthScale = truthScaleOf(truthPath, truth);
  std::vector<double> truthVolumes = particleVolumesOf(truth);
  for (double& v : truthVolumes) v /= truthScale * truthScale * truthScale;
  for (double& v : volumes) v /= scale * scale * scale;
  for (double& v : blockVolumes) v /= scale * scale * scale;
  sectionOptions.step = truthScale / scale;
  const SectionStatistics truthSections = sampleSections(truth.dims, truth.particleId, sectionOptions);
  nlohmann::json report =
      comparisonJson(compareSections(truthSections, solidSections, diameter), "truth_sections");
  report.update({{"truth", truthPath},
                 {"particles", truthVolumes.size()},
                 {"mean_volume", mean(truthVolumes)},
                 {"section_ks", ksStatistic(truthSections.areas, solidSections.areas)}});
  report.update(volumeDistances(truthVolumes, volumes));
  if (band) report["volume_cdf_band"] = bandCoverage(*band, truthVolumes);
  if (!blockVolumes.empty()) report["whole_in_block"] = volumeDistances(truthVolumes, blockVolumes);
  truthOut = std::move(truthVolumes);
  return report;
}

// The materials descriptors of the photo's colour classes and of the solid's voxels by their
// nearest class, with the classes' centres.
nlohmann::json colourMaterials(const CompareJob& job, const cv::Mat& photo, const SolidVolume& volume,
                               double scale, const MaterialsOptions& materials) {
  if (!volume.hasColor())
    throw InputError(job.volume + " has no colour grid: --phases and --phase-mask classify colours");
  if (job.phases != 0 && (job.phases < 2 || job.phases > 8)) throw OptionError("--phases must be in [2, 8]");
  const ColourClasses classes =
      job.phaseMask ? colourClassesOfLabels(photo, loadPhoto(*job.phaseMask), *job.phaseMask + ": phase mask")
                    : colourClasses(photo, job.phases, job.sections.seed);
  const int count = classes.centres.rows;
  if (job.phases > 0 && count > job.phases)
    throw InputError(*job.phaseMask + " has " + std::to_string(count) + " phases, more than --phases " +
                     std::to_string(job.phases));
  cv::Mat photoClasses;
  cv::resize(classes.labels, photoClasses,
             cv::Size(std::max(1, int(std::lround(photo.cols * scale))),
                      std::max(1, int(std::lround(photo.rows * scale)))),
             0, 0, cv::INTER_NEAREST);
  std::vector<Rgb> colours(volume.dims.count());
  for (int k = 0; k < volume.dims.z; ++k)
    for (int j = 0; j < volume.dims.y; ++j)
      for (int i = 0; i < volume.dims.x; ++i) colours[volume.dims.index(i, j, k)] = volume.colorAt(i, j, k);
  const std::vector<std::uint8_t> voxelClasses = nearestClasses(colours, classes.centres);
  colours = {};
  nlohmann::json report =
      materialsReport(classPhases(photoClasses, volume.dims, voxelClasses, count), materials);
  report["classes"] = {{"method", job.phaseMask ? "phase mask " + *job.phaseMask : "k-means in CIE L*a*b*"},
                       {"centres_lab", nlohmann::json::array()}};
  for (int c = 0; c < classes.centres.rows; ++c)
    report["classes"]["centres_lab"].push_back(
        {classes.centres.at<float>(c, 0), classes.centres.at<float>(c, 1), classes.centres.at<float>(c, 2)});
  return report;
}

// The comparison plot with the materials descriptors' curves below it, when the report has them.
cv::Mat withMaterials(const cv::Mat& plot, const nlohmann::json& report) {
  if (!report.contains("materials")) return plot;
  constexpr int kMinWidth = 1560;  // four curve panels of 390 pixels
  const int width = std::max(plot.cols, kMinWidth);
  const cv::Mat curves = plotMaterials(report["materials"], width);
  if (curves.empty()) return plot;
  cv::Mat top, both;
  cv::copyMakeBorder(plot, top, 0, 0, 0, width - plot.cols, cv::BORDER_CONSTANT, cv::Scalar(1, 1, 1));
  cv::vconcat(top, curves, both);
  return both;
}

nlohmann::json compareParticles(const CompareJob& job, const cv::Mat& photo, const SolidVolume& volume,
                                cv::Mat* plot) {
  if (job.reference)
    throw OptionError("--reference is for continuous solids; give --truth for particle solids");
  if (job.sections.offsetsPerAxis < 1 || job.sections.offsetsPerAxis > 4096)
    throw OptionError("--axis-planes must be in [1, 4096]");
  if (job.sections.obliquePlanes < 0 || job.sections.obliquePlanes > 100000)
    throw OptionError("--oblique-planes must be in [0, 100000]");
  if (job.sections.planeAxis < -1 || job.sections.planeAxis > 2)
    throw OptionError("the plane's axis must be 0 (yz), 1 (xz) or 2 (xy), or -1 for all");
  // The descriptors average sections of every axis, and the seams lie across every axis too.
  if (job.sections.planeAxis >= 0 && ((job.measures && job.measures->any()) || job.brickEdge > 0))
    throw OptionError("--plane compares one plane's sections: give --measures none and no --bricks with it");
  if (volume.particleId.empty())
    throw InputError(job.volume + " has no particle_id grid: not a particle solid");
  const ExemplarStats stats = analyzeExemplar(photo, job.photo, job.segmentation);
  const double scale = scaleOf(job, volume);

  std::vector<double> photoAreas;
  for (std::size_t i : statisticalParticles(stats.particles))
    photoAreas.push_back(stats.particles[i].area * scale * scale);
  const double diameter = meanParticleDiameter(stats) * scale;
  SectionOptions sectionOptions = job.sections;
  sectionOptions.minArea = stats.minArea * scale * scale;
  const cv::Mat labels = photoLabels(stats, scale);
  sectionOptions.windowSide = arrangementWindowSide(diameter, volume.dims, labels.size());
  const SectionStatistics sections = sampleSections(volume.dims, volume.particleId, sectionOptions);
  const SectionStatistics photoSections = measureLabelImage(labels, sectionOptions);
  const SectionComparison shapes = compareSections(photoSections, sections, diameter);
  const std::vector<double> blockVolumes = particleVolumesOf(volume);
  const std::optional<WholeParticleVolumes> placed = readWholeVolumesMetadata(volume.metadata, job.volume);
  const std::vector<double>& volumes = placed ? placed->volumes : blockVolumes;
  std::size_t occupied = 0;
  for (std::int32_t id : volume.particleId) occupied += id > 0;

  ComparisonData data{photoAreas,
                      sections.areas,
                      stats.histogram.ratios,
                      tenBinRatios(volumes),
                      shapes.referenceSolidity,
                      shapes.solidSolidity};
  if (std::optional<VolumeCdfBand> band = volumeBandOf(volume, job.volume)) {
    data.volumeBand = std::move(*band);
    for (double v : volumes) data.solidVolumes.push_back(v / (scale * scale * scale));
  }
  if (placed) {
    char label[64];
    std::snprintf(label, sizeof label, "solid volumes, whole (%.1f %% cut away)", 100 * placed->cutShare);
    data.volumeLabel = label;
  }
  const double photoMean = mean(photoAreas);
  nlohmann::json report = {
      {"mode", "particles"},
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
      {"sections",
       {{"planes", sections.planes}, {"count", sections.areas.size()}, {"mean_area", mean(sections.areas)}}},
      {"photo_mean_area", photoMean},
      {"ks", ksStatistic(photoAreas, sections.areas)},
      {"ks_critical_95", ksCritical95(photoAreas.size(), sections.areas.size())},
      {"wasserstein1_over_mean", photoMean > 0 ? wasserstein1(photoAreas, sections.areas) / photoMean : 0.0},
      {"shape_and_arrangement", comparisonJson(shapes, "photo")},
      {"window_side", sectionOptions.windowSide},
      {"particle_diameter", diameter}};
  report["volume_sample"] = volumeSampleOf(volume, placed.has_value());
  if (nlohmann::json phases = phaseComparison(stats, volume, job.volume, scale, sectionOptions, diameter);
      !phases.is_null())
    report["phases"] = std::move(phases);
  if (placed)
    report["whole_in_block"] = {{"particles", blockVolumes.size()},
                                {"mean_volume", mean(blockVolumes)},
                                {"volume_histogram", tenBinRatios(blockVolumes)},
                                {"placed_cut_share", placed->cutShare},
                                {"placed_cut_particles", placed->cutParticles}};
  if (job.truth)
    report["truth"] =
        compareWithTruth(*job.truth, volumes, placed ? blockVolumes : std::vector<double>{},
                         data.volumeBand.volumes.empty() ? std::nullopt : std::optional(data.volumeBand),
                         scale, sections, sectionOptions, diameter, data.truthVolumes);
  MaterialsOptions materials = job.materials;
  if (job.measures) materials.measures = *job.measures;
  if (job.sections.planeAxis >= 0) materials.measures = parseMeasureSelection("none");
  if (materials.measures.any()) {
    const auto boundary = volume.metadata.find("boundary");
    materials.periodic = boundary != volume.metadata.end() && boundary->second == "periodic";
    report["materials"] =
        job.measuresClasses()
            ? colourMaterials(job, photo, volume, scale, materials)
            : materialsReport(particleAndMatrixPhases(labels, volume.dims, volume.particleId), materials);
  }
  if (job.brickEdge > 0)
    report["brick_seams"] =
        brickSeamsReport(volume.particleId, volume.dims, job.brickEdge, sectionOptions.windowSide);
  if (plot) *plot = withMaterials(plotComparison(data, report), report);
  return report;
}

// The exemplar, the reference, a middle axis slice and an oblique slice side by side, each scaled
// to the same height.
cv::Mat continuousPlot(const cv::Mat& exemplar, const cv::Mat& reference, const SolidVolume& volume) {
  const Eigen::Vector3d centre(0.5 * (volume.dims.x - 1), 0.5 * (volume.dims.y - 1),
                               0.5 * (volume.dims.z - 1));
  std::vector<cv::Mat> panels{exemplar};
  if (!reference.empty()) panels.push_back(reference);
  panels.push_back(colorSlice(volume, axisPlane(volume.dims, 2, volume.dims.z / 2)));
  panels.push_back(colorSlice(volume, obliquePlane(volume.dims, Eigen::Vector3d(1, 2, 3), centre)));
  const int height = std::max(256, exemplar.rows);
  std::vector<cv::Mat> row;
  for (const cv::Mat& panel : panels) {
    cv::Mat scaled;
    const double f = double(height) / panel.rows;
    cv::resize(panel, scaled, cv::Size(std::max(1, int(std::lround(panel.cols * f))), height), 0, 0,
               cv::INTER_NEAREST);
    row.push_back(scaled);
    row.push_back(cv::Mat(height, 8, CV_32FC3, cv::Scalar(1, 1, 1)));
  }
  row.pop_back();
  cv::Mat out;
  cv::hconcat(row, out);
  return out;
}

nlohmann::json compareContinuous(const CompareJob& job, const cv::Mat& exemplar, const SolidVolume& volume,
                                 const cv::Mat& reference, cv::Mat* plot) {
  if (job.truth) throw OptionError("--truth is for particle solids; give --reference for continuous solids");
  if (job.brickEdge > 0) throw OptionError("--bricks measures the seams of particle solids");
  if (job.measures && job.measures->any() && !job.measuresClasses())
    throw OptionError(
        "--measures on a continuous solid needs --phases K or --phase-mask (its colour classes)");
  ContinuousQualityOptions qualityOptions = job.quality;
  qualityOptions.planeAxis = job.sections.planeAxis;
  const ContinuousQuality quality = measureContinuousSolid(volume, exemplar, reference, qualityOptions);
  nlohmann::json report = {{"mode", "continuous"},
                           {"exemplar", job.photo},
                           {"volume", job.volume},
                           {"dims", {volume.dims.x, volume.dims.y, volume.dims.z}},
                           {"quality", continuousQualityJson(quality, qualityOptions)}};
  if (job.sections.planeAxis >= 0) report["plane"] = planeNameOf(job.sections.planeAxis);
  if (job.reference) report["reference"] = *job.reference;
  MaterialsOptions materials = job.materials;
  if (job.measures) materials.measures = *job.measures;
  if (job.measuresClasses() && materials.measures.any()) {
    const double scale = job.voxelsPerPixel > 0 ? job.voxelsPerPixel : 1.0;
    report["materials"] = colourMaterials(job, exemplar, volume, scale, materials);
  }
  if (plot) *plot = withMaterials(continuousPlot(exemplar, reference, volume), report);
  return report;
}

bool comparesParticles(const CompareJob& job, const SolidVolume& volume) {
  return job.mode == CompareMode::Particles || (job.mode == CompareMode::Auto && !volume.particleId.empty());
}

}  // namespace

nlohmann::json brickSeamsReport(const std::vector<std::int32_t>& ids, const Dims& dims, int brickEdge,
                                int windowSide) {
  constexpr int kDepth = 4;
  const BrickSeams s = brickSeams(ids, dims, brickEdge, kDepth, windowSide);
  return {{"edge", brickEdge},
          {"depth", kDepth},
          {"window_side", windowSide},
          {"face_planes", s.facePlanes},
          {"other_planes", s.otherPlanes},
          {"face_fraction", s.faceFraction},
          {"other_fraction", s.otherFraction},
          {"face_window_spread", s.faceWindowSpread},
          {"other_window_spread", s.otherWindowSpread}};
}

CompareMode parseCompareMode(const std::string& name) {
  if (name == "auto") return CompareMode::Auto;
  if (name == "particles") return CompareMode::Particles;
  if (name == "continuous") return CompareMode::Continuous;
  throw OptionError("unknown compare mode '" + name + "' (expected auto, particles or continuous)");
}

nlohmann::json compareSolid(const CompareJob& job, const cv::Mat& photo, const SolidVolume& volume,
                            const cv::Mat& reference, cv::Mat* plot) {
  return comparesParticles(job, volume) ? compareParticles(job, photo, volume, plot)
                                        : compareContinuous(job, photo, volume, reference, plot);
}

SolidVolume readSolidToCompare(const std::string& path, CompareMode mode, bool colour) {
  if (mode == CompareMode::Continuous || colour) return readVdb(path);
  SolidVolume volume = readVdb(path, kParticleIdsOnly);
  return mode == CompareMode::Auto && volume.particleId.empty() ? readVdb(path) : volume;
}

nlohmann::json runCompare(const CompareJob& job) {
  OutputFiles outputs;
  for (const auto& input : {std::optional(job.photo), std::optional(job.volume), job.truth, job.reference,
                            job.segmentation.maskPath, job.phaseMask})
    if (input) outputs.addInput(*input);
  if (job.plot) outputs.addFile("--plot", *job.plot, {".png"});
  addReport(outputs, job.report);
  const SolidVolume volume = readSolidToCompare(job.volume, job.mode, job.measuresClasses());
  const cv::Mat photo = loadPhoto(job.photo);
  const cv::Mat reference =
      job.reference && !comparesParticles(job, volume) ? loadPhoto(*job.reference) : cv::Mat();
  cv::Mat plot;
  nlohmann::json report = compareSolid(job, photo, volume, reference, job.plot ? &plot : nullptr);
  if (job.plot) outputs.write(*job.plot, [&](const std::string& path) { writeImage(path, plot); });
  writeReport(outputs, job.report, report);
  outputs.commit();
  return report;
}

}  // namespace solidtex
