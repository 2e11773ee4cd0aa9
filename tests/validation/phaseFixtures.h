#pragma once
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "validation/PhaseField.h"

namespace solidtex::testing {

/// The voxels whose centres satisfy `in`.
inline PhaseField fieldWhere(const Dims& dims, const std::function<bool(double, double, double)>& in) {
  PhaseField f{dims, std::vector<std::uint8_t>(dims.count())};
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) f.inside[dims.index(i, j, k)] = in(i, j, k);
  return f;
}

/// A Boolean model on a periodic cube of side n: balls of `radius` about Poisson points, as many as
/// make the expected uncovered (matrix) fraction `matrix`. Returns the matrix phase; `intensity`
/// receives the number density of the points drawn.
inline PhaseField booleanBallsMatrix(int n, double radius, double matrix, unsigned seed, double* intensity) {
  const double ball = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  *intensity = -std::log(matrix) / ball;
  std::mt19937_64 rng(seed);
  std::poisson_distribution<int> count(*intensity * n * n * n);
  std::uniform_real_distribution<double> at(0.0, n);
  const Dims dims{n, n, n};
  PhaseField f{dims, std::vector<std::uint8_t>(dims.count(), 1)};
  const int reach = int(std::ceil(radius));
  const int balls = count(rng);
  *intensity = balls / (double(n) * n * n);
  for (int b = balls; b > 0; --b) {
    const double cx = at(rng), cy = at(rng), cz = at(rng);
    for (int k = int(cz) - reach - 1; k <= int(cz) + reach + 1; ++k)
      for (int j = int(cy) - reach - 1; j <= int(cy) + reach + 1; ++j)
        for (int i = int(cx) - reach - 1; i <= int(cx) + reach + 1; ++i) {
          const double dx = i - cx, dy = j - cy, dz = k - cz;
          if (dx * dx + dy * dy + dz * dz > radius * radius) continue;
          f.inside[dims.index(((i % n) + n) % n, ((j % n) + n) % n, ((k % n) + n) % n)] = 0;
        }
  }
  return f;
}

}  // namespace solidtex::testing
