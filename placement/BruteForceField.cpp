// Brute-force spaciousness (paper 3.7): after each insertion every voxel within maxRadius of the new
// particle is re-evaluated against all of the particle's boundary voxels. Exact, and slow on
// purpose: it is the reference the faster fields are measured against.
#include <cmath>

#include <tbb/parallel_for.h>

#include "placement/detail/BucketField.h"

namespace solidtex::placement::detail {
namespace {

// Squared distance from (x,y,z) to the box: a lower bound of the distance to anything inside it.
std::int64_t squaredGapToBox(int x, int y, int z, const Box& box) {
  const auto gap = [](int v, int lo, int hi) {
    return std::int64_t(v < lo ? lo - v : v >= hi ? v - hi + 1 : 0);
  };
  const std::int64_t gx = gap(x, box.lo.x, box.hi.x), gy = gap(y, box.lo.y, box.hi.y),
                     gz = gap(z, box.lo.z, box.hi.z);
  return gx * gx + gy * gy + gz * gz;
}

template <class Key>
class BruteForceField final : public BucketField<Key> {
public:
  BruteForceField(Dims dims, float maxRadius, bool periodic)
      : BucketField<Key>(dims, periodic, squaredDistanceValues(maxRadius),
                         [](int wall) { return std::uint64_t(wall) * std::uint64_t(wall); }) {}

  PlacerKind kind() const override { return PlacerKind::Brute; }

  void insert(const std::vector<Voxel>& voxels) override {
    this->occupy(voxels);
    if (voxels.empty()) return;
    const std::vector<Voxel> boundary = boundaryVoxels(voxels);
    for (const Voxel& shift : this->imageShifts(voxels)) lowerTowards(shifted(boundary, shift));
  }

private:
  // Lowers the voxels within the cap of the boundary voxels (some may lie outside the volume: images
  // of a periodic volume's particle) to their distance from them.
  void lowerTowards(std::vector<Voxel> boundary) {
    boundary_ = std::move(boundary);
    const Box box = boundingBox(boundary_);
    const int reach = int(std::ceil(std::sqrt(double(this->capKey()))));
    const Dims& d = this->dims_;
    const Box region{
        {std::max(box.lo.x - reach, 0), std::max(box.lo.y - reach, 0), std::max(box.lo.z - reach, 0)},
        {std::min(box.hi.x + reach, d.x), std::min(box.hi.y + reach, d.y), std::min(box.hi.z + reach, d.z)}};
    // Slices are evaluated in parallel; their changes are applied in slice order for determinism.
    std::vector<std::vector<std::pair<VoxelIndex, Key>>> changes(std::size_t(region.hi.z - region.lo.z));
    tbb::parallel_for(region.lo.z, region.hi.z,
                      [&](int z) { evaluateSlice(z, region, box, changes[std::size_t(z - region.lo.z)]); });
    for (const auto& slice : changes)
      for (const auto& [v, key] : slice) this->queue_.lower(v, key);
  }

  void evaluateSlice(int z, const Box& region, const Box& box,
                     std::vector<std::pair<VoxelIndex, Key>>& changes) const {
    for (int y = region.lo.y; y < region.hi.y; ++y)
      for (int x = region.lo.x; x < region.hi.x; ++x) {
        const VoxelIndex v = VoxelIndex(this->dims_.index(x, y, z));
        const std::int64_t old = this->queue_.key(v);
        if (squaredGapToBox(x, y, z, box) >= old) continue;  // also skips occupied voxels
        std::int64_t best = old;
        for (const Voxel& b : boundary_) best = std::min(best, squaredDistance({x, y, z}, b));
        if (best < old) changes.emplace_back(v, Key(best));
      }
  }

  std::vector<Voxel> boundary_;
};

}  // namespace

std::unique_ptr<SpaciousnessField> makeBruteForceField(Dims dims, float maxRadius, bool periodic) {
  return makeWithNarrowestKey<BruteForceField>(squaredDistanceValues(maxRadius).size() - 1, dims, maxRadius,
                                               periodic);
}

}  // namespace solidtex::placement::detail
