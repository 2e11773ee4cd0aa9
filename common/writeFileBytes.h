#pragma once
#include <cstddef>
#include <string>

namespace solidtex {

/// Writes `size` bytes to `path` (created or truncated), checking every write and the close: a full
/// disk or a vanished folder throws InputError naming the path and the system's reason, never
/// leaves a silently truncated file behind a success.
void writeFileBytes(const std::string& path, const void* data, std::size_t size);

}  // namespace solidtex
