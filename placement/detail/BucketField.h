#pragma once
// Internal: the part shared by the fields that keep a value for every voxel (discrete, brute, edt).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include <tbb/parallel_for.h>

#include "placement/SpaciousnessField.h"
#include "placement/detail/BucketQueue.h"
#include "placement/detail/voxelSets.h"

namespace solidtex::placement::detail {

/// Stores an integer key per voxel; values_[key] is the spaciousness it stands for (non-decreasing
/// in the key, values_[0] = 0 for occupied voxels, the last key is the cap).
template <class Key>
class BucketField : public SpaciousnessField {
public:
  Dims dims() const override { return dims_; }
  bool periodic() const override { return periodic_; }
  float maxRadius() const override { return values_.back(); }

  float at(const Voxel& v) const override {
    checkInside(dims_, v);
    return values_[queue_.key(index(v))];
  }

  std::vector<Voxel> bestFit(float radius, int maxCount, Rng& rng) override {
    const auto first = std::lower_bound(values_.begin() + 1, values_.end(), radius);
    if (first == values_.end() || maxCount <= 0) return {};
    std::vector<VoxelIndex> picked;
    queue_.sample(std::size_t(first - values_.begin()), std::size_t(maxCount), rng, picked);
    std::vector<Voxel> spots;
    spots.reserve(picked.size());
    for (VoxelIndex v : picked) spots.push_back(dims_.voxel(v));
    return spots;
  }

  std::vector<Voxel> randomFit(float radius, int maxCount, Rng& rng) override {
    const auto first = std::lower_bound(values_.begin() + 1, values_.end(), radius);
    std::vector<Voxel> spots;
    if (first == values_.end() || maxCount <= 0) return spots;
    queue_.sampleUniformly(std::size_t(first - values_.begin()), std::size_t(maxCount), rng,
                           [&](VoxelIndex v) { spots.push_back(dims_.voxel(v)); });
    return spots;
  }

  std::size_t bytes() const { return queue_.bytes() + values_.capacity() * sizeof(float); }

protected:
  /// keyOfWall(d): the key of a voxel whose nearest wall layer is d voxels away (before the cap).
  template <class KeyOfWall>
  BucketField(Dims dims, bool periodic, std::vector<float> values, KeyOfWall keyOfWall)
      : dims_(dims),
        periodic_(periodic),
        values_(std::move(values)),
        queue_(initialKeys(dims, periodic, capKey(), keyOfWall), capKey()) {}

  VoxelIndex index(const Voxel& v) const { return VoxelIndex(dims_.index(v)); }
  Key capKey() const { return Key(values_.size() - 1); }

  /// Checks the voxels of an insertion and marks them occupied (key 0).
  void occupy(const std::vector<Voxel>& voxels) {
    if (!periodic_) checkInside(dims_, voxels);
    for (const Voxel& v : voxels) {
      const VoxelIndex i = index(periodic_ ? dims_.wrap(v) : v);
      if (queue_.key(i) != 0) queue_.lower(i, 0);
    }
  }

  /// The shifts of the voxels (a particle: insert()'s argument) whose distances the volume's voxels
  /// can see below the cap: the voxels themselves, and in a periodic volume their images across the faces.
  std::vector<Voxel> imageShifts(const std::vector<Voxel>& voxels) const {
    if (!periodic_) return {Voxel{}};
    return periodicShifts(dims_, boundingBox(voxels), int(std::ceil(double(values_.back()))));
  }

  Dims dims_;
  bool periodic_;
  std::vector<float> values_;
  BucketQueue<Key> queue_;

private:
  template <class KeyOfWall>
  static std::vector<Key> initialKeys(Dims dims, bool periodic, Key cap, KeyOfWall keyOfWall) {
    std::vector<Key> keys(dims.count(), cap);
    if (periodic) return keys;
    tbb::parallel_for(0, dims.z, [&](int k) {
      for (int j = 0; j < dims.y; ++j)
        for (int i = 0; i < dims.x; ++i)
          keys[dims.index(i, j, k)] =
              Key(std::min<std::uint64_t>(keyOfWall(wallDistance(dims, i, j, k)), cap));
    });
    return keys;
  }
};

/// The narrowest unsigned type that holds keys up to maxKey.
template <template <class> class Field, class... Args>
std::unique_ptr<SpaciousnessField> makeWithNarrowestKey(std::uint64_t maxKey, Args&&... args) {
  if (maxKey <= std::numeric_limits<std::uint8_t>::max())
    return std::make_unique<Field<std::uint8_t>>(args...);
  if (maxKey <= std::numeric_limits<std::uint16_t>::max())
    return std::make_unique<Field<std::uint16_t>>(args...);
  return std::make_unique<Field<std::uint32_t>>(args...);
}

/// Values for squared-distance keys: sqrt(key), the last key (ceil(maxRadius^2)) standing for maxRadius.
std::vector<float> squaredDistanceValues(float maxRadius);

}  // namespace solidtex::placement::detail
