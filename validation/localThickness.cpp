#include "validation/localThickness.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "common/Error.h"
#include "common/squaredDistanceTransform.h"

namespace solidtex {

namespace {

// Squared distance from every voxel to the nearest voxel outside the phase.
std::vector<std::uint32_t> squaredDepth(const PhaseField& phase) {
  std::vector<std::uint8_t> outside(phase.inside.size());
  for (std::size_t i = 0; i < outside.size(); ++i) outside[i] = !phase.inside[i];
  return squaredDistanceToSites(phase.dims, outside);
}

double largestOf(const PhaseField& phase, const std::vector<std::uint32_t>& depth) {
  std::uint32_t deepest = 0;
  for (std::size_t i = 0; i < depth.size(); ++i)
    if (phase.inside[i] && depth[i] != kNoSite) deepest = std::max(deepest, depth[i]);
  return std::max(1.0, std::sqrt(double(deepest)));
}

}  // namespace

double largestInscribedRadius(const PhaseField& phase) { return largestOf(phase, squaredDepth(phase)); }

LocalThickness localThickness(const PhaseField& phase, const LocalThicknessOptions& options) {
  if (options.sizes < 1) throw OptionError("local thickness needs at least one sphere size");
  const std::size_t n = phase.inside.size();
  const std::vector<std::uint32_t> depth = squaredDepth(phase);

  LocalThickness out;
  out.radius.assign(n, 0.0f);
  const double largest = options.largest > 0 ? std::max(1.0, options.largest) : largestOf(phase, depth);
  std::size_t phaseVoxels = 0, covered = 0;
  for (std::uint8_t in : phase.inside) phaseVoxels += in;
  if (phaseVoxels == 0) return out;
  std::vector<std::uint8_t> centre(n);
  std::vector<std::uint32_t> reach;
  for (int s = 0; s < options.sizes; ++s) {
    const double r = options.sizes == 1 ? 1.0 : std::pow(largest, 1.0 - double(s) / (options.sizes - 1));
    if (!out.sizes.empty() && r >= out.sizes.back()) continue;
    // r is a rounded power, often of a whole squared distance (sqrt 2 from 2^0.5): ties go as they
    // would without rounding, centres at distance r included and voxels at distance r not covered.
    const double r2 = r * r * (1 - 1e-9);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& b) {
      for (std::size_t i = b.begin(); i != b.end(); ++i)
        centre[i] = phase.inside[i] && double(depth[i]) >= r2;
    });
    squaredDistanceToSites(phase.dims, centre, reach);
    covered += tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n), std::size_t(0),
        [&](const tbb::blocked_range<std::size_t>& b, std::size_t newly) {
          for (std::size_t i = b.begin(); i != b.end(); ++i)
            if (phase.inside[i] && out.radius[i] == 0 && double(reach[i]) < r2) {
              out.radius[i] = float(r);
              ++newly;
            }
          return newly;
        },
        std::plus<>());
    out.sizes.push_back(r);
    out.cumulative.push_back(double(covered) / double(phaseVoxels));
  }
  return out;
}

}  // namespace solidtex
