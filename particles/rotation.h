#pragma once
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "common/Random.h"

namespace solidtex {

/// A rotation drawn uniformly from SO(3) (Shoemake's quaternion method) with three uniform01 draws.
inline Eigen::Matrix3d randomRotation(Rng& rng) {
  const double u1 = uniform01(rng), u2 = uniform01(rng), u3 = uniform01(rng);
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1), twoPi = 2 * std::numbers::pi;
  const Eigen::Quaterniond q(b * std::cos(twoPi * u3), a * std::sin(twoPi * u2), a * std::cos(twoPi * u2),
                             b * std::sin(twoPi * u3));
  return q.toRotationMatrix();
}

}  // namespace solidtex
