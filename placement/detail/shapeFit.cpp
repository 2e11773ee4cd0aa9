#include "placement/detail/shapeFit.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "placement/detail/voxelSets.h"

namespace solidtex::placement::detail {
namespace {

Voxel nearestShapeVoxel(const VoxelShape& shape, const Voxel& centre) {
  Voxel best = centre;
  std::int64_t bestSquared = std::numeric_limits<std::int64_t>::max();
  for (int k = 0; k < shape.dims.z; ++k)
    for (int j = 0; j < shape.dims.y; ++j)
      for (int i = 0; i < shape.dims.x; ++i)
        if (shape.inside[shape.dims.index(i, j, k)] != 0 &&
            squaredDistance({i, j, k}, centre) < bestSquared) {
          best = {i, j, k};
          bestSquared = squaredDistance(best, centre);
        }
  return best;
}

// Distance from the anchor to the nearest voxel that is not the shape's: inside the box, or just
// outside it on an axis.
double innerRadiusOf(const VoxelShape& shape, const Voxel& a) {
  const Dims& d = shape.dims;
  std::int64_t nearest = std::min({a.x + 1, d.x - a.x, a.y + 1, d.y - a.y, a.z + 1, d.z - a.z});
  nearest *= nearest;
  for (int k = 0; k < d.z; ++k)
    for (int j = 0; j < d.y; ++j)
      for (int i = 0; i < d.x; ++i)
        if (shape.inside[d.index(i, j, k)] == 0) nearest = std::min(nearest, squaredDistance({i, j, k}, a));
  return std::sqrt(double(nearest));
}

}  // namespace

FitShape prepareShape(const VoxelShape& shape) {
  FitShape fit;
  fit.dims = shape.dims;
  fit.pose = shape.pose;
  fit.anchor = nearestShapeVoxel(shape, {shape.dims.x / 2, shape.dims.y / 2, shape.dims.z / 2});
  fit.innerRadius = float(innerRadiusOf(shape, fit.anchor));
  // Counting sort by squared distance, farthest first: the outer voxels are where collisions happen.
  std::vector<std::pair<Voxel, std::int32_t>> all;
  std::int32_t most = 0;
  for (int k = 0; k < shape.dims.z; ++k)
    for (int j = 0; j < shape.dims.y; ++j)
      for (int i = 0; i < shape.dims.x; ++i)
        if (shape.inside[shape.dims.index(i, j, k)] != 0) {
          all.emplace_back(Voxel{i, j, k}, std::int32_t(squaredDistance({i, j, k}, fit.anchor)));
          most = std::max(most, all.back().second);
        }
  std::vector<std::size_t> start(std::size_t(most) + 2);
  for (const auto& [v, s] : all) ++start[std::size_t(most - s) + 1];
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  fit.voxels.resize(all.size());
  fit.squared.resize(all.size());
  for (const auto& [v, s] : all) {
    const std::size_t at = start[std::size_t(most - s)]++;
    fit.voxels[at] = v;
    fit.squared[at] = s;
  }
  fit.outerRadius = float(std::sqrt(double(most) + 1));
  return fit;
}

bool fitsAt(const FitShape& shape, const Voxel& spot, float spaciousness, const VoxelBits& occupied,
            Dims dims, bool periodic) {
  const Voxel o = originAt(shape, spot);
  if (periodic) {
    if (shape.dims.x > dims.x || shape.dims.y > dims.y || shape.dims.z > dims.z) return false;
  } else if (o.x < 0 || o.y < 0 || o.z < 0 || o.x + shape.dims.x > dims.x || o.y + shape.dims.y > dims.y ||
             o.z + shape.dims.z > dims.z) {
    return false;
  }
  // Squared distances are integers: d < s exactly when d^2 < s^2 - 1/2, whatever the float rounding of s.
  const double known = double(spaciousness) * double(spaciousness) - 0.5;
  for (std::size_t i = 0; i < shape.voxels.size() && shape.squared[i] >= known; ++i) {
    const Voxel& v = shape.voxels[i];
    const Voxel at{o.x + v.x, o.y + v.y, o.z + v.z};
    if (occupied.test(dims.index(periodic ? dims.wrap(at) : at))) return false;
  }
  return true;
}

}  // namespace solidtex::placement::detail
