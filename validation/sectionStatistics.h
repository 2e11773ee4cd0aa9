#pragma once
#include <cstdint>
#include <vector>

#include "common/Grid.h"

namespace solidtex {

/// Which planes cut the volume.
struct SectionOptions {
  int offsetsPerAxis = 16;      ///< evenly spaced axis-aligned planes per axis
  int obliquePlanes = 32;       ///< random orientations through random points near the centre
  double minArea = 0;           ///< smaller sections are specks and dropped, as the photo's noise is
  std::uint64_t seed = 1;
};

/// Cross-sections of the particles of an id volume (0 = background) on many planes.
struct SectionStatistics {
  std::vector<double> areas;    ///< voxel^2, one per cross-section not cut by the volume's walls
  double areaFraction = 0;      ///< particle pixels / all pixels over every plane
  int planes = 0;
};

/// Cuts the volume with axis-aligned and random oblique planes and measures every cross-section:
/// an 8-connected set of pixels of one particle id, as the photo's contours are (a concave particle
/// may give several). Planes nearly tangent to a voxel surface still cut it into specks, which
/// `minArea` drops as the photo's analysis drops its noise. Sections cut by the volume's walls are counted in the area fraction but not in `areas`, just as the
/// photo's border particles are left out of its histogram.
SectionStatistics sampleSections(const Dims& dims, const std::vector<std::int32_t>& ids, const SectionOptions& options);

/// Two-sample Kolmogorov-Smirnov statistic: the largest gap between the empirical CDFs.
double ksStatistic(std::vector<double> a, std::vector<double> b);

/// Wasserstein-1 (earth mover's) distance between two empirical distributions on the line.
double wasserstein1(std::vector<double> a, std::vector<double> b);

} // namespace solidtex
