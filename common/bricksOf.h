#pragma once
/// @file bricksOf.h
/// @brief The bricks that cut a volume into boxes worked on one at a time.
#include <algorithm>
#include <vector>

#include "common/Box.h"

namespace solidtex {

/// The boxes of edge `edge` that tile a volume of `dims`, x fastest, then y, then z; the last along
/// an axis is thinner where `edge` does not divide it. `edge` <= 0: the whole volume.
inline std::vector<Box> bricksOf(const Dims& dims, int edge) {
  if (edge <= 0) return {Box::of(dims)};
  std::vector<Box> bricks;
  for (int z = 0; z < dims.z; z += edge)
    for (int y = 0; y < dims.y; y += edge)
      for (int x = 0; x < dims.x; x += edge)
        bricks.push_back(
            {{x, y, z},
             {std::min(x + edge, dims.x), std::min(y + edge, dims.y), std::min(z + edge, dims.z)}});
  return bricks;
}

}  // namespace solidtex
