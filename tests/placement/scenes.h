#pragma once
// Small scenes of occupied voxels and the exact spaciousness they imply, for the placement tests.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/Grid.h"
#include "common/Random.h"

namespace solidtex::test {

/// Occupancy of a small volume, filled by random balls and boxes that never overlap. A periodic
/// scene is a 3D torus: particles run across its faces and distances wrap around it.
class Scene {
public:
  explicit Scene(Dims dims, bool periodic = false)
      : dims_(dims), periodic_(periodic), occupied_(dims.count()) {}

  Dims dims() const { return dims_; }
  bool occupied(const Voxel& v) const { return occupied_[dims_.index(v)] != 0; }

  /// Adds a random ball or box (its free voxels only) and returns its voxels; empty when it lands
  /// entirely on occupied voxels. A periodic scene returns them unwrapped, as a field takes them:
  /// running past the faces.
  std::vector<Voxel> addRandomParticle(Rng& rng) {
    const Voxel c{int(uniformIndex(rng, std::uint64_t(dims_.x))),
                  int(uniformIndex(rng, std::uint64_t(dims_.y))),
                  int(uniformIndex(rng, std::uint64_t(dims_.z)))};
    const int r = 1 + int(uniformIndex(rng, 4));
    const bool ball = uniformIndex(rng, 2) == 0;
    std::vector<Voxel> voxels;
    for (int k = c.z - r; k <= c.z + r; ++k)
      for (int j = c.y - r; j <= c.y + r; ++j)
        for (int i = c.x - r; i <= c.x + r; ++i) {
          const int dx = i - c.x, dy = j - c.y, dz = k - c.z;
          const Voxel inside = periodic_ ? dims_.wrap({i, j, k}) : Voxel{i, j, k};
          if (!dims_.contains(inside.x, inside.y, inside.z) || occupied(inside)) continue;
          if (ball && dx * dx + dy * dy + dz * dz > r * r) continue;
          occupied_[dims_.index(inside)] = 1;
          voxels.push_back({i, j, k});
        }
    return voxels;
  }

  /// Exact spaciousness of every voxel, in index order, by brute force: the distance to the
  /// nearest occupied voxel or wall layer; in a periodic scene, to the nearest occupied voxel around
  /// the torus.
  std::vector<double> exactField() const {
    std::vector<Voxel> occupied;
    for (std::size_t i = 0; i < occupied_.size(); ++i)
      if (occupied_[i]) occupied.push_back(dims_.voxel(i));
    std::vector<double> out(dims_.count());
    for (std::size_t i = 0; i < out.size(); ++i) {
      const Voxel v = dims_.voxel(i);
      double best = periodic_
                        ? 1e30
                        : std::min({v.x + 1, dims_.x - v.x, v.y + 1, dims_.y - v.y, v.z + 1, dims_.z - v.z});
      best *= best;
      const auto gap = [&](int a, int b, int n) {
        const int d = std::abs(a - b);
        return double(periodic_ ? std::min(d, n - d) : d);
      };
      for (const Voxel& p : occupied) {
        const double dx = gap(p.x, v.x, dims_.x), dy = gap(p.y, v.y, dims_.y), dz = gap(p.z, v.z, dims_.z);
        best = std::min(best, dx * dx + dy * dy + dz * dz);
      }
      out[i] = std::sqrt(best);
    }
    return out;
  }

private:
  Dims dims_;
  bool periodic_;
  std::vector<std::uint8_t> occupied_;
};

}  // namespace solidtex::test
