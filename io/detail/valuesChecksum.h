#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <openvdb/openvdb.h>

namespace solidtex::io::detail {

// A .vdb has no checksum of its own, and damaged Blosc data can decode to valid-looking values:
// solidtex's files carry one per grid in the grid's metadata, under this name (16 hex digits).
inline constexpr const char* kValuesChecksumName = "solidtex_values_checksum";

// A 64-bit checksum of a float, int32 or Vec3s grid's topology and active values (leaves hashed in
// parallel, combined in tree order: the same at any thread count); nullopt for other grid types
// and for grids saved as half floats.
std::optional<std::uint64_t> valuesChecksum(const openvdb::GridBase& grid);

// The same checksum built from its parts, for a writer that makes a grid's leaves a batch at a
// time: each leaf's hash, then all of them in tree order with the tree's tiles.
std::uint64_t leafChecksum(const openvdb::Vec3STree::LeafNodeType& leaf);
std::uint64_t valuesChecksum(const openvdb::Vec3STree& tree, const std::vector<std::uint64_t>& leafChecksums);

// The checksum as the metadata keeps it.
std::string checksumText(std::uint64_t checksum);

}  // namespace solidtex::io::detail
