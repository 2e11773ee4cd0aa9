#pragma once
// Internal: one bit per voxel, for sets that are tested far more often than they change.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace solidtex::placement::detail {

/// A set of voxel indices as a bit array: 1/32 of an int32 grid, so it stays in cache.
class VoxelBits {
public:
  explicit VoxelBits(std::size_t count) : words_((count + 63) / 64) {}

  bool test(std::size_t i) const { return (words_[i / 64] >> (i % 64)) & 1; }
  void set(std::size_t i) { words_[i / 64] |= bitOf(i); }
  /// Sets i; whether it was set before.
  bool testAndSet(std::size_t i) {
    const bool was = test(i);
    set(i);
    return was;
  }
  /// Clears i and the other 63 indices that share its word: the cheap way to empty a set whose
  /// members are all known.
  void clearWordOf(std::size_t i) { words_[i / 64] = 0; }

private:
  static std::uint64_t bitOf(std::size_t i) { return std::uint64_t(1) << (i % 64); }
  std::vector<std::uint64_t> words_;
};

}  // namespace solidtex::placement::detail
