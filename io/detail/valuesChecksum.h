#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include <openvdb/openvdb.h>

namespace solidtex::io::detail {

// A .vdb has no checksum of its own, and damaged Blosc data can decode to valid-looking values:
// solidtex's files carry one per grid in the grid's metadata, under this name (16 hex digits).
inline constexpr const char* kValuesChecksumName = "solidtex_values_checksum";

// A 64-bit checksum of a float, int32 or Vec3s grid's topology and active values (leaves hashed in
// parallel, combined in tree order: the same at any thread count); nullopt for other grid types.
std::optional<std::uint64_t> valuesChecksum(const openvdb::GridBase& grid);

// The checksum as the metadata keeps it.
std::string checksumText(std::uint64_t checksum);

}  // namespace solidtex::io::detail
