#pragma once
#include <cstddef>
#include <vector>

#include "common/Grid.h"

namespace solidtex {

/// Values of `channels` floats per voxel (1: density, 3: linear RGB), x fastest, channel innermost:
/// voxel (i,j,k)'s channel c is values[dims.index(i,j,k) * channels + c].
struct DenseVolume {
  Dims dims;
  int channels = 1;
  std::vector<float> values;

  const float* at(int i, int j, int k) const { return &values[dims.index(i, j, k) * std::size_t(channels)]; }
  float* at(int i, int j, int k) { return &values[dims.index(i, j, k) * std::size_t(channels)]; }
};

}  // namespace solidtex
