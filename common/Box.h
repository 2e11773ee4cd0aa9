#pragma once
#include "common/Grid.h"

namespace solidtex {

/// A box of voxels, [lo, hi) on each axis: half-open, so its size is hi - lo and boxes that tile a
/// volume share the coordinates of the faces between them.
struct Box {
  Voxel lo, hi;

  /// The whole grid of `dims`, from the origin.
  static Box of(const Dims& dims) { return {{0, 0, 0}, {dims.x, dims.y, dims.z}}; }
  /// `dims` voxels from `lo`.
  static Box at(const Voxel& lo, const Dims& dims) {
    return {lo, {lo.x + dims.x, lo.y + dims.y, lo.z + dims.z}};
  }

  Dims dims() const { return {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}; }
  bool empty() const { return hi.x <= lo.x || hi.y <= lo.y || hi.z <= lo.z; }
  bool contains(const Voxel& v) const {
    return v.x >= lo.x && v.y >= lo.y && v.z >= lo.z && v.x < hi.x && v.y < hi.y && v.z < hi.z;
  }
  friend bool operator==(const Box&, const Box&) = default;
};

}  // namespace solidtex
