#include "validation/localThickness.h"

#include <algorithm>
#include <cmath>

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
  for (int s = 0; s < options.sizes; ++s) {
    const double r = options.sizes == 1 ? 1.0 : std::pow(largest, 1.0 - double(s) / (options.sizes - 1));
    if (!out.sizes.empty() && r >= out.sizes.back()) continue;
    std::vector<std::uint8_t> centre(n);
    for (std::size_t i = 0; i < n; ++i) centre[i] = phase.inside[i] && double(depth[i]) >= r * r;
    const std::vector<std::uint32_t> reach = squaredDistanceToSites(phase.dims, centre);
    for (std::size_t i = 0; i < n; ++i)
      if (phase.inside[i] && out.radius[i] == 0 && double(reach[i]) < r * r) {
        out.radius[i] = float(r);
        ++covered;
      }
    out.sizes.push_back(r);
    out.cumulative.push_back(double(covered) / double(phaseVoxels));
  }
  return out;
}

}  // namespace solidtex
