#pragma once
/// @file
/// Cross-sections of a particle solid on many planes, measured as a photo's particles are.

#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "common/Grid.h"
#include "segmentation/regionShape.h"

namespace solidtex {

/// Which planes cut the volume and what is measured on them.
struct SectionOptions {
  int offsetsPerAxis = 16;  ///< evenly spaced axis-aligned planes per axis
  int obliquePlanes = 32;   ///< random orientations through random points near the centre
  /// -1: every axis; 0, 1, 2: only the planes across x (yz), y (xz) or z (xy), as one plane's photo
  /// shows an anisotropic material (oblique planes are then still cut if asked for).
  int planeAxis = -1;
  double minArea = 0;        ///< smaller sections are specks and dropped, as the photo's noise is
  double shapeMinArea = 20;  ///< samples; smaller sections are too coarse for a shape
  int windowSide = 0;        ///< samples per side of the arrangement windows; 0: no arrangement measures
  double step = 1;           ///< voxels between samples: a finer volume cut at a coarser one's resolution
  std::uint64_t seed = 1;
};

/// The axis a plane named "xy", "xz" or "yz" holds fixed (2, 1, 0), as SectionOptions::planeAxis
/// takes it; throws OptionError otherwise.
int planeAxisOf(const std::string& plane);
/// The plane an axis holds fixed: "yz", "xz" or "xy" for 0, 1, 2.
std::string planeNameOf(int axis);

/// Cross-sections of the particles of an id volume (0 = background) on many planes. Sizes and
/// positions are in samples (`SectionOptions::step` voxels apart).
struct SectionStatistics {
  std::vector<double> areas;               ///< one per cross-section not cut by the walls, at least minArea
  std::vector<RegionShape> shapes;         ///< axis planes only: the uncut sections of at least shapeMinArea
  std::vector<double> windowFractions;     ///< axis planes only: their windows lie wholly in the volume
  std::vector<double> neighbourDistances;  ///< axis planes only: centroid to nearest centroid
  double areaFraction = 0;                 ///< particle pixels / all pixels over every plane
  int planes = 0;
};

/// Cuts the volume with axis-aligned and random oblique planes and measures every cross-section:
/// an 8-connected set of pixels of one particle id, as the photo's contours are (a concave particle
/// may give several). Planes nearly tangent to a voxel surface still cut it into specks, which
/// `minArea` drops as the photo's analysis drops its noise. Sections cut by the volume's walls
/// count in the area fraction and as neighbours but are not measured, just as the photo's border
/// particles are left out of its histogram.
SectionStatistics sampleSections(const Dims& dims, const std::vector<std::int32_t>& ids,
                                 const SectionOptions& options);

/// The same measures of one label image (CV_32S, 0 background, regions of equal positive labels),
/// such as a photo's particles resampled to a solid's voxels: it counts as one axis plane.
SectionStatistics measureLabelImage(const cv::Mat& labels, const SectionOptions& options);

}  // namespace solidtex
