#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace solidtex {

/// Bytes in memory, one part of a file.
struct ByteSpan {
  const void* data = nullptr;
  std::size_t size = 0;
};

/// Writes `size` bytes to `path` (created or truncated), checking every write and the close: a full
/// disk or a vanished folder throws InputError naming the path and the system's reason, never
/// leaves a silently truncated file behind a success.
void writeFileBytes(const std::string& path, const void* data, std::size_t size);

/// Writes the parts one after the other, as writeFileBytes: a header and the arrays it describes
/// without copying them into one buffer.
void writeFileBytes(const std::string& path, const std::vector<ByteSpan>& parts);

}  // namespace solidtex
