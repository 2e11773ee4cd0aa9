#pragma once
// Small scenes of occupied voxels and the exact spaciousness they imply, for the placement tests.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/Grid.h"
#include "common/Random.h"

namespace solidtex::test {

/// Occupancy of a small volume, filled by random balls and boxes that never overlap.
class Scene {
public:
  explicit Scene(Dims dims) : dims_(dims), occupied_(dims.count()) {}

  Dims dims() const { return dims_; }
  bool occupied(const Voxel& v) const { return occupied_[dims_.index(v)] != 0; }

  /// Adds a random ball or box (its free voxels only) and returns its voxels; empty when it lands
  /// entirely on occupied voxels.
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
          if (!dims_.contains(i, j, k) || occupied({i, j, k})) continue;
          if (ball && dx * dx + dy * dy + dz * dz > r * r) continue;
          occupied_[dims_.index(i, j, k)] = 1;
          voxels.push_back({i, j, k});
        }
    return voxels;
  }

  /// Exact spaciousness of every voxel, in index order, by brute force: the distance to the
  /// nearest occupied voxel or wall layer.
  std::vector<double> exactField() const {
    std::vector<Voxel> occupied;
    for (std::size_t i = 0; i < occupied_.size(); ++i)
      if (occupied_[i]) occupied.push_back(dims_.voxel(i));
    std::vector<double> out(dims_.count());
    for (std::size_t i = 0; i < out.size(); ++i) {
      const Voxel v = dims_.voxel(i);
      double best = std::min({v.x + 1, dims_.x - v.x, v.y + 1, dims_.y - v.y, v.z + 1, dims_.z - v.z});
      best *= best;
      for (const Voxel& p : occupied) {
        const double dx = p.x - v.x, dy = p.y - v.y, dz = p.z - v.z;
        best = std::min(best, dx * dx + dy * dy + dz * dz);
      }
      out[i] = std::sqrt(best);
    }
    return out;
  }

private:
  Dims dims_;
  std::vector<std::uint8_t> occupied_;
};

}  // namespace solidtex::test
