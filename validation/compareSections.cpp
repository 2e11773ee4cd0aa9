#include "validation/compareSections.h"

#include <cmath>
#include <numbers>

#include "common/distributionDistance.h"
#include "segmentation/resampleRegions.h"
#include "validation/arrangement.h"

namespace solidtex {
namespace {

ShapeColumns columnsOf(const std::vector<RegionShape>& shapes) {
  ShapeColumns c;
  for (const RegionShape& s : shapes) c.add(s);
  return c;
}

// Orientations in steps of 5 degrees, taken round the circle: the major axis of a section ten
// pixels long is known to about that. Finer, the digitization of nearly aligned sections would
// decide the statistic (a symmetric voxel shape's exact 0 against a photo's sub-degree spread).
std::vector<double> orientationSteps(std::vector<double> radians) {
  constexpr double kStep = std::numbers::pi / 36;
  for (double& r : radians) r = std::fmod(std::round(r / kStep) * kStep, std::numbers::pi);
  return radians;
}

SectionSummary summarize(const SectionStatistics& s, const ShapeColumns& columns, double diameter) {
  SectionSummary out;
  out.shapes = s.shapes.size();
  out.solidity = mean(columns.solidity);
  out.roundness = mean(columns.roundness);
  out.aspect = mean(columns.aspect);
  out.windows = s.windowFractions.size();
  out.windowSpread = standardDeviation(s.windowFractions);
  out.neighbours = s.neighbourDistances.size();
  out.neighbourDistance = diameter > 0 ? mean(s.neighbourDistances) / diameter : 0;
  return out;
}

}  // namespace

SectionComparison compareSections(const SectionStatistics& reference, const SectionStatistics& solid,
                                  double diameter) {
  const ShapeColumns r = columnsOf(reference.shapes), s = columnsOf(solid.shapes);
  SectionComparison c;
  c.reference = summarize(reference, r, diameter);
  c.solid = summarize(solid, s, diameter);
  c.solidityKs = ksStatistic(r.solidity, s.solidity);
  c.roundnessKs = ksStatistic(r.roundness, s.roundness);
  c.aspectKs = ksStatistic(r.aspect, s.aspect);
  // Round sections on both sides have no orientation to differ in.
  c.orientationKs = r.orientation.empty() && s.orientation.empty()
                        ? 0
                        : kuiperStatistic(orientationSteps(r.orientation), orientationSteps(s.orientation));
  c.shapeKsCritical = ksCritical95(r.solidity.size(), s.solidity.size());
  c.windowSpreadRatio = c.reference.windowSpread > 0 ? c.solid.windowSpread / c.reference.windowSpread : 0;
  c.neighbourKs = ksStatistic(reference.neighbourDistances, solid.neighbourDistances);
  c.neighbourRatio =
      c.reference.neighbourDistance > 0 ? c.solid.neighbourDistance / c.reference.neighbourDistance : 0;
  c.referenceSolidity = r.solidity;
  c.solidSolidity = s.solidity;
  return c;
}

cv::Mat photoLabels(const ExemplarStats& stats, double voxelsPerPixel) {
  cv::Mat labels = cv::Mat::zeros(stats.imageHeight, stats.imageWidth, CV_32S);
  for (std::size_t i = 0; i < stats.particles.size(); ++i) {
    const Particle2D& p = stats.particles[i];
    labels(p.box).setTo(cv::Scalar(int(i) + 1), p.mask);
  }
  return resampleLabels(labels, voxelsPerPixel);
}

double meanParticleDiameter(const ExemplarStats& stats) {
  double sum = 0;
  const std::vector<std::size_t> counted = statisticalParticles(stats.particles);
  for (std::size_t i : counted) sum += stats.particles[i].area;
  return counted.empty() ? 0 : std::sqrt(4 / std::numbers::pi * sum / double(counted.size()));
}

}  // namespace solidtex
