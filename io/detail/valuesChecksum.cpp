#include "io/detail/valuesChecksum.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <openvdb/tree/LeafManager.h>
#include <tbb/parallel_for.h>

namespace solidtex::io::detail {
namespace {

// One multiply-xorshift step per 32-bit word (every value type here is made of them).
struct Hash {
  std::uint64_t state = 0x9e3779b97f4a7c15ull;
  void add(std::uint64_t word) {
    state = (state ^ word) * 0xff51afd7ed558ccdull;
    state ^= state >> 32;
  }
  template <class T>
  void addBytes(const T& value) {
    static_assert(sizeof(T) % 4 == 0);
    std::uint32_t words[sizeof(T) / 4];
    std::memcpy(words, &value, sizeof(T));
    for (const std::uint32_t w : words) add(w);
  }
};

template <class LeafT>
std::uint64_t leafHash(const LeafT& leaf) {
  Hash h;
  h.addBytes(leaf.origin());
  for (openvdb::Index w = 0; w < LeafT::NodeMaskType::WORD_COUNT; ++w)
    h.add(leaf.getValueMask().template getWord<std::uint64_t>(w));
  for (auto value = leaf.cbeginValueOn(); value; ++value) h.addBytes(*value);
  return h.state;
}

template <class TreeT>
std::uint64_t combined(const TreeT& tree, const std::vector<std::uint64_t>& leafHashes) {
  Hash total;
  for (const std::uint64_t leafHash : leafHashes) total.add(leafHash);
  typename TreeT::ValueOnCIter tile = tree.cbeginValueOn();
  tile.setMaxDepth(TreeT::ValueOnCIter::LEAF_DEPTH - 1);
  for (; tile; ++tile) {
    total.addBytes(tile.getCoord());
    total.add(tile.getDepth());
    total.addBytes(tile.getValue());
  }
  return total.state;
}

template <class GridT>
std::uint64_t checksumOf(const GridT& grid) {
  using TreeT = typename GridT::TreeType;
  const openvdb::tree::LeafManager<const TreeT> leaves(grid.tree());
  std::vector<std::uint64_t> leafHashes(leaves.leafCount());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.leafCount()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i < range.end(); ++i)
                        leafHashes[i] = leafHash(leaves.leaf(i));
                    });
  return combined(grid.tree(), leafHashes);
}

}  // namespace

std::optional<std::uint64_t> valuesChecksum(const openvdb::GridBase& grid) {
  std::optional<std::uint64_t> checksum;
  if (grid.saveFloatAsHalf()) return checksum;  // its values are read back rounded
  grid.apply<openvdb::TypeList<openvdb::FloatGrid, openvdb::Int32Grid, openvdb::Vec3SGrid>>(
      [&](const auto& typed) { checksum = checksumOf(typed); });
  return checksum;
}

std::uint64_t leafChecksum(const openvdb::Vec3STree::LeafNodeType& leaf) { return leafHash(leaf); }

std::uint64_t valuesChecksum(const openvdb::Vec3STree& tree,
                             const std::vector<std::uint64_t>& leafChecksums) {
  return combined(tree, leafChecksums);
}

std::string checksumText(std::uint64_t checksum) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(checksum));
  return text;
}

}  // namespace solidtex::io::detail
