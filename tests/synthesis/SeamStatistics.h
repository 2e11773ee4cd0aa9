#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <ostream>
#include <vector>

#include "common/Grid.h"

namespace solidtex::test {

/// A statistic of neighbouring voxel pairs averaged over each plane between two layers: the interior
/// planes (layer i to i + 1) of all three axes, and each axis's wrap plane (layer N - 1 to 0), where
/// two copies of a periodic volume placed side by side meet. A pyramid makes planes differ by their
/// place modulo its levels' blocks (a coarse level's 2x2x2 parity classes are 4x4x4 blocks a level
/// finer; voxels of one block share a parent and agree more often): only the interior planes at
/// the wrap plane's place modulo `period` count.
struct PlaneMeans {
  std::vector<double> interior;
  std::array<double, 3> wrap{};

  double mean() const {
    double sum = 0;
    for (double v : interior) sum += v;
    return sum / double(interior.size());
  }
  double sd() const {
    const double m = mean();
    double sum = 0;
    for (double v : interior) sum += (v - m) * (v - m);
    return std::sqrt(sum / double(interior.size() - 1));
  }
  /// Whether v is as an interior plane's value would be: within the interior mean +- 3 sd.
  bool likeInterior(double v) const { return std::abs(v - mean()) <= 3 * sd(); }
  double wrapMean() const { return (wrap[0] + wrap[1] + wrap[2]) / 3; }
  /// How far the mean of three interior planes strays from their mean: 3 sd / sqrt(3).
  double band() const { return std::sqrt(3.0) * sd(); }

  friend std::ostream& operator<<(std::ostream& out, const PlaneMeans& p) {
    const auto [lo, hi] = std::minmax_element(p.interior.begin(), p.interior.end());
    return out << "interior mean " << p.mean() << " sd " << p.sd() << " range [" << *lo << ", " << *hi
               << "], wrap planes x " << p.wrap[0] << " y " << p.wrap[1] << " z " << p.wrap[2];
  }
};

/// `pair(a, b, axis)` for every voxel a and its neighbour b one step further along `axis`
/// (wrapping), averaged per plane; sides must be multiples of `period`.
template <class Pair>
PlaneMeans planeMeans(const Dims& dims, int period, Pair&& pair) {
  PlaneMeans out;
  const std::array<int, 3> n{dims.x, dims.y, dims.z};
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    for (int layer = 0; layer < n[axis]; ++layer) {
      double sum = 0;
      for (int j = 0; j < n[w]; ++j)
        for (int i = 0; i < n[u]; ++i) {
          std::array<int, 3> a{}, b{};
          a[axis] = layer, a[u] = i, a[w] = j;
          b = a;
          b[axis] = (layer + 1) % n[axis];
          sum += pair(Voxel{a[0], a[1], a[2]}, Voxel{b[0], b[1], b[2]}, axis);
        }
      const double value = sum / (double(n[u]) * n[w]);
      if (layer + 1 == n[axis])
        out.wrap[std::size_t(axis)] = value;
      else if (layer % period == period - 1)
        out.interior.push_back(value);
    }
  }
  return out;
}

}  // namespace solidtex::test
