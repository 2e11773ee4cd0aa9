#pragma once
/// @file
/// A solid's cross-sections against a reference: the photo's particles or a truth's sections.

#include <cstddef>
#include <vector>

#include <opencv2/core.hpp>

#include "segmentation/ExemplarStats.h"
#include "validation/sectionStatistics.h"

namespace solidtex {

/// Means of one side's shape and arrangement measures.
struct SectionSummary {
  std::size_t shapes = 0;  ///< regions measured for shape
  double solidity = 0, roundness = 0, aspect = 0;
  std::size_t windows = 0;
  double windowSpread = 0;  ///< standard deviation of the windows' area fractions
  std::size_t neighbours = 0;
  double neighbourDistance = 0;  ///< mean centroid to nearest centroid, in particle diameters
};

/// Shape (solidity, roundness) and arrangement (window spread, nearest neighbours) of a solid's
/// sections against a reference's: KS distances and solid / reference ratios.
struct SectionComparison {
  SectionSummary reference, solid;
  double solidityKs = 1, roundnessKs = 1;
  double aspectKs = 1;       ///< minor / major axis of the sections
  double orientationKs = 1;  ///< Kuiper's (circular) KS of the elongated sections' major axes in the plane
  double shapeKsCritical =
      1;  ///< the KS two samples of these sizes from one distribution exceed 1 time in 20
  double windowSpreadRatio = 0;  ///< solid / reference: above 1 is more clustered
  double neighbourKs = 1;
  double neighbourRatio = 0;  ///< solid / reference mean nearest-neighbour distance
  std::vector<double> referenceSolidity, solidSolidity;  ///< for plots
};

/// Compares two sets of section measures taken at the same resolution; `diameter` (samples) is the
/// unit of the nearest-neighbour distances.
SectionComparison compareSections(const SectionStatistics& reference, const SectionStatistics& solid,
                                  double diameter);

/// The photo's particles as a label image (CV_32S, 1..P) resampled by `voxelsPerPixel` to a solid's
/// voxels (resampleLabels), so their shapes are measured at the resolution the solid can show.
cv::Mat photoLabels(const ExemplarStats& stats, double voxelsPerPixel);

/// Equivalent-disc diameter of the photo's mean statistical particle, in photo pixels.
double meanParticleDiameter(const ExemplarStats& stats);

}  // namespace solidtex
