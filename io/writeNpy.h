#pragma once
/// @file
/// Arrays as numpy `.npy` files (format 1.0), readable by `numpy.load`.

#include <cstddef>
#include <string>
#include <vector>

namespace solidtex {

/// Writes a C-ordered (last axis fastest) little-endian array of `shape` whose elements are
/// `descr` ("<f4" float32, "<i4" int32, ...), checking every write. `data` holds
/// product(shape) elements of `elementSize` bytes. Throws InputError when the file cannot be written.
void writeNpy(const std::string& path, const std::string& descr, const std::vector<std::size_t>& shape,
              const void* data, std::size_t elementSize);

/// The .npy header (magic, version, dictionary padded so the data starts at a multiple of 64 bytes).
std::string npyHeader(const std::string& descr, const std::vector<std::size_t>& shape);

}  // namespace solidtex
