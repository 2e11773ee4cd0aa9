#pragma once
#include <cmath>

#include <Eigen/Core>

#include "common/Random.h"

namespace solidtex {

/// A uniformly distributed unit vector: rejection sampling in the unit ball, then normalised.
inline Eigen::Vector3d randomDirection(Rng& rng) {
  while (true) {
    const Eigen::Vector3d d(2 * uniform01(rng) - 1, 2 * uniform01(rng) - 1, 2 * uniform01(rng) - 1);
    const double n = d.squaredNorm();
    if (n > 1e-6 && n <= 1) return d / std::sqrt(n);
  }
}

}  // namespace solidtex
