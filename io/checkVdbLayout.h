#pragma once
#include <string>
#include <vector>

namespace solidtex {

/// Walks a .vdb's header, file metadata, grid descriptors, each grid's metadata and transform type
/// and, for the common map and value types, its root node's tiles, before OpenVDB reads it, and
/// throws InputError naming the file for any length or offset that points past its end (a
/// truncated or damaged file) or a tile's active flag that is neither 0 nor 1. OpenVDB itself would allocate
/// whatever a damaged length says: a "grid type" of gigabytes, or memory until the system kills the process.
/// Returns each grid's number of root tiles, -1 where the walk did not reach them (an instance, a
/// streamed file, another map or value type).
std::vector<long> checkVdbLayout(const std::string& path);

}  // namespace solidtex
