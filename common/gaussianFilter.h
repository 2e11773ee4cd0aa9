#pragma once
/// @file gaussianFilter.h
/// @brief Separable Gaussian filtering of volumes, one axis at a time.
#include <vector>

#include "common/Grid.h"

namespace solidtex {

/// Normalised Gaussian weights for offsets -r..r, r = ceil(3 sigma) and at least 1; {1} for
/// sigma <= 0.
std::vector<float> gaussianKernel(double sigma);

/// out = in correlated with `kernel` (offsets -r..r) along `axis` (0 x, 1 y, 2 z), clamped at the
/// edges: out(i) = sum_t kernel[t + r] in(clamp(i + t)). `channels` values per voxel, x fastest;
/// `out` holds as many values as `in` and is not `in`. Parallel over z slices.
void correlateAlong(const float* in, float* out, const Dims& dims, int channels, int axis,
                    const std::vector<float>& kernel);

}  // namespace solidtex
