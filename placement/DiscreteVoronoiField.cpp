// Discrete Voronoi spaciousness (paper 3.7, Fig. 5 and Fig. 6): 26-neighbour step counts from the
// occupied voxels, propagated outwards from each new particle only where they drop.
#include <array>
#include <cmath>

#include "placement/detail/BucketField.h"

namespace solidtex::placement::detail {
namespace {

// Key k stands for k steps; the last key stands for maxRadius. A step count is the Chebyshev
// distance, so Euclidean / sqrt(3) <= value <= Euclidean.
std::vector<float> stepValues(float maxRadius) {
  std::vector<float> values(std::size_t(std::ceil(maxRadius)) + 1);
  for (std::size_t k = 0; k + 1 < values.size(); ++k) values[k] = float(k);
  values.back() = maxRadius;
  return values;
}

template <class Key>
class DiscreteVoronoiField final : public BucketField<Key> {
public:
  DiscreteVoronoiField(Dims dims, float maxRadius, bool periodic)
      : BucketField<Key>(dims, periodic, stepValues(maxRadius),
                         [](int wall) { return std::uint64_t(wall); }) {
    const std::ptrdiff_t sx = 1, sy = dims.x, sz = std::ptrdiff_t(dims.x) * dims.y;
    std::size_t n = 0;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (dx != 0 || dy != 0 || dz != 0) offsets_[n++] = {dx, dy, dz, dx * sx + dy * sy + dz * sz};
  }

  PlacerKind kind() const override { return PlacerKind::Discrete; }

  // Fig. 6: the particle's voxels drop to 0, then a FIFO queue walks outwards and lowers every
  // neighbour whose value exceeds its predecessor's + 1. Seeding with the particle's boundary
  // voxels suffices (see boundaryVoxels), and level order makes each value final when first set.
  // In a periodic volume the walk steps across the faces.
  void insert(const std::vector<Voxel>& voxels) override {
    this->occupy(voxels);
    frontier_.clear();
    for (const Voxel& v : boundaryVoxels(voxels))
      frontier_.push_back(this->index(this->periodic_ ? this->dims_.wrap(v) : v));
    for (std::size_t head = 0; head < frontier_.size(); ++head) relaxNeighbours(frontier_[head]);
  }

private:
  struct Offset {
    int dx, dy, dz;
    std::ptrdiff_t linear;
  };

  void relaxNeighbours(VoxelIndex v) {
    const std::uint64_t next = std::uint64_t(this->queue_.key(v)) + 1;
    if (next >= this->capKey()) return;
    const Dims& d = this->dims_;
    const int x = int(v % VoxelIndex(d.x)), y = int(v / VoxelIndex(d.x) % VoxelIndex(d.y)),
              z = int(v / (VoxelIndex(d.x) * VoxelIndex(d.y)));
    const bool interior = x > 0 && y > 0 && z > 0 && x + 1 < d.x && y + 1 < d.y && z + 1 < d.z;
    for (const Offset& o : offsets_) {
      VoxelIndex n = 0;
      if (interior)
        n = VoxelIndex(std::ptrdiff_t(v) + o.linear);
      else if (this->periodic_)
        n = this->index(d.wrap({x + o.dx, y + o.dy, z + o.dz}));
      else if (d.contains(x + o.dx, y + o.dy, z + o.dz))
        n = this->index({x + o.dx, y + o.dy, z + o.dz});
      else
        continue;
      if (this->queue_.key(n) > next) {
        this->queue_.lower(n, Key(next));
        frontier_.push_back(n);
      }
    }
  }

  std::array<Offset, 26> offsets_{};
  std::vector<VoxelIndex> frontier_;
};

}  // namespace

std::unique_ptr<SpaciousnessField> makeDiscreteVoronoiField(Dims dims, float maxRadius, bool periodic) {
  return makeWithNarrowestKey<DiscreteVoronoiField>(std::uint64_t(std::ceil(maxRadius)), dims, maxRadius,
                                                    periodic);
}

}  // namespace solidtex::placement::detail
