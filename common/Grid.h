#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

namespace solidtex {

/// Integer voxel coordinate.
struct Voxel {
  int x = 0, y = 0, z = 0;
  friend bool operator==(const Voxel&, const Voxel&) = default;
};

/// Extent of a dense grid; x varies fastest in linear indices.
struct Dims {
  int x = 0, y = 0, z = 0;
  std::size_t count() const { return std::size_t(x) * std::size_t(y) * std::size_t(z); }
  std::size_t index(int i, int j, int k) const {
    return (std::size_t(k) * std::size_t(y) + std::size_t(j)) * std::size_t(x) + std::size_t(i);
  }
  std::size_t index(const Voxel& v) const { return index(v.x, v.y, v.z); }
  Voxel voxel(std::size_t idx) const {
    return {int(idx % std::size_t(x)), int((idx / std::size_t(x)) % std::size_t(y)),
            int(idx / (std::size_t(x) * std::size_t(y)))};
  }
  bool contains(int i, int j, int k) const { return i >= 0 && j >= 0 && k >= 0 && i < x && j < y && k < z; }
  /// v's image inside the grid taken as a 3D torus, whose opposite faces meet.
  Voxel wrap(const Voxel& v) const { return {wrapped(v.x, x), wrapped(v.y, y), wrapped(v.z, z)}; }
  friend bool operator==(const Dims&, const Dims&) = default;

private:
  static int wrapped(int v, int n) {
    v %= n;
    return v < 0 ? v + n : v;
  }
};

}  // namespace solidtex
