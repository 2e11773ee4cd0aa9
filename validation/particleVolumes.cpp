#include "validation/particleVolumes.h"

#include <algorithm>
#include <numeric>

namespace solidtex {
namespace {

struct ParticleExtent {
  double voxels = 0;
  Voxel lo{1 << 30, 1 << 30, 1 << 30}, hi{-1, -1, -1};
};

std::vector<ParticleExtent> extentsOf(const Dims& dims, const std::vector<std::int32_t>& ids) {
  std::vector<ParticleExtent> extents;
  for (int z = 0; z < dims.z; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) {
        const std::int32_t id = ids[dims.index(x, y, z)];
        if (id <= 0) continue;
        if (std::size_t(id) > extents.size()) extents.resize(std::size_t(id));
        ParticleExtent& e = extents[std::size_t(id - 1)];
        e.voxels += 1;
        e.lo = {std::min(e.lo.x, x), std::min(e.lo.y, y), std::min(e.lo.z, z)};
        e.hi = {std::max(e.hi.x, x), std::max(e.hi.y, y), std::max(e.hi.z, z)};
      }
  return extents;
}

bool touchesFace(const ParticleExtent& e, const Dims& dims) {
  return e.lo.x == 0 || e.lo.y == 0 || e.lo.z == 0 || e.hi.x == dims.x - 1 || e.hi.y == dims.y - 1 ||
         e.hi.z == dims.z - 1;
}

// Places a box of the particle's extent fits in the volume without touching a face.
double placesInside(const ParticleExtent& e, const Dims& dims) {
  return double(dims.x - 1 - (e.hi.x - e.lo.x + 1)) * double(dims.y - 1 - (e.hi.y - e.lo.y + 1)) *
         double(dims.z - 1 - (e.hi.z - e.lo.z + 1));
}

// Equally weighted quantiles (i + 1/2) / n of a weighted sample, n its size.
std::vector<double> weightedQuantiles(std::vector<std::pair<double, double>> weighted) {
  std::sort(weighted.begin(), weighted.end());
  const double total = std::accumulate(weighted.begin(), weighted.end(), 0.0,
                                       [](double sum, const auto& v) { return sum + v.second; });
  std::vector<double> quantiles;
  const std::size_t n = weighted.size();
  double below = 0;  // weight of the values before `next`
  std::size_t next = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double target = (double(i) + 0.5) / double(n) * total;
    while (next + 1 < n && below + weighted[next].second < target) below += weighted[next++].second;
    quantiles.push_back(weighted[next].first);
  }
  return quantiles;
}

}  // namespace

std::vector<double> particleVolumes(const Dims& dims, const std::vector<std::int32_t>& ids, bool cutByFaces) {
  std::vector<std::pair<double, double>> weighted;  // volume, weight
  for (const ParticleExtent& e : extentsOf(dims, ids)) {
    if (e.voxels == 0) continue;
    if (!cutByFaces) {
      weighted.emplace_back(e.voxels, 1.0);
      continue;
    }
    const double places = placesInside(e, dims);
    if (!touchesFace(e, dims) && places > 0) weighted.emplace_back(e.voxels, 1.0 / places);
  }
  if (!cutByFaces) {
    std::vector<double> volumes;
    for (const auto& [v, w] : weighted) volumes.push_back(v);
    return volumes;
  }
  return weightedQuantiles(std::move(weighted));
}

}  // namespace solidtex
