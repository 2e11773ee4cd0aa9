#include "placement/detail/voxelSets.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/Error.h"

namespace solidtex::placement::detail {

void checkFieldArguments(Dims dims, float maxRadius) {
  if (dims.x <= 0 || dims.y <= 0 || dims.z <= 0)
    throw InputError("spaciousness field: volume dimensions must be positive, got " + std::to_string(dims.x) +
                     "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z));
  if (dims.count() >= std::size_t(std::numeric_limits<VoxelIndex>::max()))
    throw InputError("spaciousness field: volume of " + std::to_string(dims.count()) +
                     " voxels is too large (at most 2^32 - 1)");
  if (!(maxRadius > 0) || !std::isfinite(maxRadius))
    throw InputError("spaciousness field: maxRadius must be positive and finite, got " +
                     std::to_string(maxRadius));
}

void checkInside(Dims dims, const Voxel& v) {
  if (!dims.contains(v.x, v.y, v.z))
    throw std::out_of_range("voxel (" + std::to_string(v.x) + "," + std::to_string(v.y) + "," +
                            std::to_string(v.z) + ") lies outside the volume");
}

void checkInside(Dims dims, const std::vector<Voxel>& voxels) {
  for (const Voxel& v : voxels) checkInside(dims, v);
}

Box boundingBox(const std::vector<Voxel>& voxels) {
  Box box{voxels.front(), voxels.front()};
  for (const Voxel& v : voxels) {
    box.lo = {std::min(box.lo.x, v.x), std::min(box.lo.y, v.y), std::min(box.lo.z, v.z)};
    box.hi = {std::max(box.hi.x, v.x), std::max(box.hi.y, v.y), std::max(box.hi.z, v.z)};
  }
  box.hi = {box.hi.x + 1, box.hi.y + 1, box.hi.z + 1};
  return box;
}

std::vector<Voxel> periodicShifts(Dims dims, const Box& box, int reach) {
  // Per axis, the multiples s of n with [lo - reach, hi + reach) + s meeting [0, n).
  const auto along = [reach](int lo, int hi, int n) {
    std::vector<int> shifts;
    for (int s = -((hi - 1 + reach) / n + 1) * n; lo - reach + s < n; s += n)
      if (hi - 1 + reach + s >= 0) shifts.push_back(s);
    return shifts;
  };
  std::vector<Voxel> out;
  for (int sz : along(box.lo.z, box.hi.z, dims.z))
    for (int sy : along(box.lo.y, box.hi.y, dims.y))
      for (int sx : along(box.lo.x, box.hi.x, dims.x)) out.push_back({sx, sy, sz});
  return out;
}

std::vector<Voxel> shifted(const std::vector<Voxel>& voxels, const Voxel& shift) {
  std::vector<Voxel> out(voxels.size());
  std::transform(voxels.begin(), voxels.end(), out.begin(), [&](const Voxel& v) {
    return Voxel{v.x + shift.x, v.y + shift.y, v.z + shift.z};
  });
  return out;
}

std::vector<Voxel> boundaryVoxels(const std::vector<Voxel>& voxels) {
  if (voxels.empty()) return {};
  const Box box = boundingBox(voxels);
  const Dims local = box.dims();
  std::vector<std::uint8_t> inside(local.count());
  for (const Voxel& v : voxels) inside[local.index(v.x - box.lo.x, v.y - box.lo.y, v.z - box.lo.z)] = 1;
  const auto in = [&](int i, int j, int k) {
    return local.contains(i, j, k) && inside[local.index(i, j, k)] != 0;
  };
  std::vector<Voxel> out;
  for (const Voxel& v : voxels) {
    const int i = v.x - box.lo.x, j = v.y - box.lo.y, k = v.z - box.lo.z;
    if (!(in(i - 1, j, k) && in(i + 1, j, k) && in(i, j - 1, k) && in(i, j + 1, k) && in(i, j, k - 1) &&
          in(i, j, k + 1)))
      out.push_back(v);
  }
  return out;
}

}  // namespace solidtex::placement::detail
