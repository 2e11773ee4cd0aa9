#include "particles/VoxelShape.h"

#include <algorithm>

namespace solidtex {

std::size_t VoxelShape::voxelCount() const {
  return std::size_t(std::count_if(inside.begin(), inside.end(), [](std::uint8_t v) { return v != 0; }));
}

std::vector<Voxel> VoxelShape::boundary() const {
  const auto in = [&](int i, int j, int k) {
    return dims.contains(i, j, k) && inside[dims.index(i, j, k)] != 0;
  };
  std::vector<Voxel> out;
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i)
        if (in(i, j, k) && !(in(i - 1, j, k) && in(i + 1, j, k) && in(i, j - 1, k) && in(i, j + 1, k) &&
                             in(i, j, k - 1) && in(i, j, k + 1)))
          out.push_back({i, j, k});
  return out;
}

}  // namespace solidtex
