#pragma once
#include <array>
#include <cstddef>

#include "synthesis/detail/NeighborhoodShape.h"
#include "synthesis/detail/WorkVolume.h"

namespace solidtex::synthesis::detail {

/// The slice orthogonal to `axis` (0 = x, 1 = y, 2 = z) maps exemplar x to volume axis u and
/// exemplar y to volume axis w: x-slices (y, z), y-slices (x, z), z-slices (x, y).
struct SliceAxes {
  int u, w;
};
inline SliceAxes sliceAxes(int axis) {
  constexpr SliceAxes table[3] = {{1, 2}, {0, 2}, {0, 1}};
  return table[axis];
}

/// Copies the neighbourhood of voxel `c` in the slice orthogonal to `axis` (periodic) into `out`
/// (shape.dims() floats, same layout as exemplar neighbourhoods).
void gatherSliceNeighborhood(const WorkVolume& volume, int axis, const std::array<int, 3>& c,
                             const NeighborhoodShape& shape, float* out);

/// The voxels where slice neighbourhoods are matched: for each axis, every voxel whose two in-plane
/// coordinates are multiples of `step` (step 1 = every voxel; 2 = a quarter, each voxel still
/// covered by (size/2)^2 neighbourhoods per axis). Ids run over axis, then along-axis coordinate,
/// then w, then u.
struct SliceCentreGrid {
  int n = 0;
  int step = 1;

  int perSide() const { return n / step; }
  std::size_t perAxis() const { return std::size_t(n) * perSide() * perSide(); }
  std::size_t count() const { return 3 * perAxis(); }
  /// Id of the centre at voxel c (in-plane coordinates multiples of step) for `axis`.
  std::size_t id(int axis, const std::array<int, 3>& c) const {
    const SliceAxes s = sliceAxes(axis);
    return axis * perAxis() + (std::size_t(c[axis]) * perSide() + c[s.w] / step) * perSide() + c[s.u] / step;
  }
  /// Axis of centre `id`.
  int axisOf(std::size_t id) const { return int(id / perAxis()); }
  /// Voxel of centre `id`.
  std::array<int, 3> voxelOf(std::size_t id) const {
    const int axis = axisOf(id);
    std::size_t r = id % perAxis();
    const SliceAxes s = sliceAxes(axis);
    std::array<int, 3> c{};
    c[s.u] = int(r % perSide()) * step;
    r /= perSide();
    c[s.w] = int(r % perSide()) * step;
    c[axis] = int(r / perSide());
    return c;
  }
};

/// Calls f(centreId, i, j) for every matched slice neighbourhood (all three axes) that covers voxel
/// `v`, where (i, j) is v's offset from that centre in slice coordinates (exemplar x, y).
/// Visits only offsets whose centre lies on the grid (every step-th), in increasing j, then i.
template <class F>
void forEachCoveringCentre(const SliceCentreGrid& grid, const NeighborhoodShape& shape,
                           const std::array<int, 3>& v, F&& f) {
  const int n = grid.n, step = grid.step;
  // The smallest offset >= lo whose centre coordinate (x - offset) is a multiple of step.
  auto firstOffset = [&](int x) {
    int r = (x - shape.lo()) % step;
    return shape.lo() + r;
  };
  auto wrap = [n](int x) { return x < 0 ? x + n : (x >= n ? x - n : x); };
  for (int axis = 0; axis < 3; ++axis) {
    const SliceAxes s = sliceAxes(axis);
    std::array<int, 3> c = v;
    for (int j = firstOffset(v[s.w]); j <= shape.hi(); j += step) {
      c[s.w] = wrap(v[s.w] - j);
      for (int i = firstOffset(v[s.u]); i <= shape.hi(); i += step) {
        c[s.u] = wrap(v[s.u] - i);
        f(grid.id(axis, c), i, j);
      }
    }
  }
}

}  // namespace solidtex::synthesis::detail
