#include "placement/exactSpaciousness.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <tbb/parallel_for.h>
#include <nanoflann.hpp>

#include "placement/detail/voxelSets.h"

namespace solidtex {
namespace {

// nanoflann's dataset interface over a list of voxel centres.
struct VoxelCloud {
  std::vector<std::array<float, 3>> points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  float kdtree_get_pt(std::size_t i, std::size_t axis) const { return points[i][axis]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using Tree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, VoxelCloud>, VoxelCloud, 3>;

// A nearest occupied voxel q of a free voxel p has a free face neighbour: the step from q towards p
// along any axis where they differ is nearer to p, so it cannot be occupied. In a periodic volume
// the steps wrap, and each such voxel comes with its images within `reach` of the volume.
VoxelCloud boundaryOf(const Dims& dims, const std::vector<std::int32_t>& ids, bool periodic, int reach) {
  VoxelCloud cloud;
  const int step[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  const auto freeAt = [&](const Voxel& n) {
    if (periodic) return ids[dims.index(dims.wrap(n))] == 0;
    return dims.contains(n.x, n.y, n.z) && ids[dims.index(n)] == 0;
  };
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] == 0) continue;
    const Voxel v = dims.voxel(i);
    if (std::none_of(std::begin(step), std::end(step), [&](const int* s) {
          return freeAt({v.x + s[0], v.y + s[1], v.z + s[2]});
        }))
      continue;
    for (const Voxel& s : periodic ? placement::detail::periodicShifts(dims, Box::at(v, {1, 1, 1}), reach)
                                   : std::vector<Voxel>{Voxel{}})
      cloud.points.push_back({float(v.x + s.x), float(v.y + s.y), float(v.z + s.z)});
  }
  return cloud;
}

}  // namespace

std::vector<float> exactSpaciousness(const Dims& dims, const std::vector<std::int32_t>& ids, float maxRadius,
                                     bool periodic) {
  if (ids.size() != dims.count()) throw std::invalid_argument("exactSpaciousness: ids do not match the dims");
  const VoxelCloud cloud = boundaryOf(dims, ids, periodic, int(std::ceil(maxRadius)));
  const Tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));  // builds the index
  std::vector<float> out(dims.count());
  tbb::parallel_for(0, dims.z, [&](int z) {
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) {
        const std::size_t i = dims.index(x, y, z);
        if (ids[i] != 0) {
          out[i] = 0;
          continue;
        }
        const int wall = std::min({x + 1, dims.x - x, y + 1, dims.y - y, z + 1, dims.z - z});
        float nearest = periodic ? maxRadius : float(wall);
        if (!cloud.points.empty()) {
          const float query[3] = {float(x), float(y), float(z)};
          std::uint32_t index = 0;
          float squared = 0;
          tree.knnSearch(query, 1, &index, &squared);
          nearest = std::min(nearest, std::sqrt(squared));
        }
        out[i] = std::min(nearest, maxRadius);
      }
  });
  return out;
}

}  // namespace solidtex
