// OpenVDB 10.0 (Debian 12) reads a value chunk of the size the file claims before comparing it
// with the buffer it reads into, and allocates what a compressed chunk claims: a damaged .vdb
// overflowed the heap (fuzzing, docs/fuzzing.md). These definitions of its two chunk readers
// replace the library's at load time (our libraries come before libopenvdb in the dynamic
// linker's search order; tests/voxel/test_checkedChunkReaders.cpp checks that they do): every
// size is checked against the buffer and the bound of its compressor before anything is
// allocated or read. The file format is OpenVDB's, unchanged.

#include <blosc.h>
#include <zlib.h>

#include <cstdint>
#include <istream>
#include <memory>
#include <string>

#include <openvdb/Exceptions.h>
#include <openvdb/io/Compression.h>

namespace openvdb {
OPENVDB_USE_VERSION_NAMESPACE
namespace OPENVDB_VERSION_NAME {
namespace io {
namespace {

[[noreturn]] void refuse(const std::string& what) { OPENVDB_THROW(RuntimeError, what); }

// The chunk's size field: negative for `numBytes` stored uncompressed, else its compressed size,
// at most `compressedBound` (its writer stores a chunk uncompressed rather than larger). A chunk
// past the end of the file then fails its read, having allocated at most that bound.
std::int64_t chunkSize(std::istream& is, std::size_t numBytes, std::uint64_t compressedBound,
                       const char* codec) {
  std::int64_t size = 0;
  if (!is.read(reinterpret_cast<char*>(&size), sizeof size))
    refuse(std::string("the file ends inside a ") + codec + " chunk's size");
  const std::uint64_t bytes = size <= 0 ? std::uint64_t(0) - std::uint64_t(size) : std::uint64_t(size);
  if (size <= 0 && bytes != numBytes)
    refuse("expected a " + std::to_string(numBytes) + "-byte uncompressed chunk, found " +
           std::to_string(bytes) + " bytes");
  if (size > 0 && std::uint64_t(size) > compressedBound)
    refuse("a " + std::string(codec) + " chunk of " + std::to_string(size) + " bytes cannot hold " +
           std::to_string(numBytes) + " bytes");
  return size;
}

// Reads or skips (data == nullptr) a chunk; returns the compressed bytes when there are some.
std::unique_ptr<char[]> readChunk(std::istream& is, char* data, std::int64_t size) {
  const auto bytes = std::streamsize(size < 0 ? -size : size);
  if (data == nullptr) {
    is.seekg(bytes, std::ios_base::cur);
    return nullptr;
  }
  std::unique_ptr<char[]> compressed;
  char* into = size <= 0 ? data : (compressed = std::make_unique<char[]>(std::size_t(bytes))).get();
  if (!is.read(into, bytes)) refuse("the file ends inside a value chunk");
  return compressed;
}

}  // namespace

void bloscFromStream(std::istream& is, char* data, size_t numBytes) {
  const std::int64_t size = chunkSize(is, numBytes, numBytes + BLOSC_MAX_OVERHEAD, "blosc");
  // blosc reads its 16-byte header before anything else.
  if (size > 0 && size < BLOSC_MIN_HEADER_LENGTH) refuse("a blosc chunk shorter than its header");
  const auto compressed = readChunk(is, data, size);
  if (!compressed) return;
  std::size_t decompressed = 0, compressedBytes = 0, blockSize = 0;
  blosc_cbuffer_sizes(compressed.get(), &decompressed, &compressedBytes, &blockSize);
  if (compressedBytes != std::size_t(size) || decompressed != numBytes ||
      blosc_decompress_ctx(compressed.get(), data, numBytes, 1) != std::int64_t(numBytes))
    refuse("a blosc chunk does not decompress to " + std::to_string(numBytes) + " bytes");
}

void unzipFromStream(std::istream& is, char* data, size_t numBytes) {
  const std::int64_t size = chunkSize(is, numBytes, compressBound(uLong(numBytes)), "zip");
  const auto compressed = readChunk(is, data, size);
  if (!compressed) return;
  uLongf unzipped = uLongf(numBytes);
  if (uncompress(reinterpret_cast<Bytef*>(data), &unzipped, reinterpret_cast<const Bytef*>(compressed.get()),
                 uLong(size)) != Z_OK ||
      unzipped != numBytes)
    refuse("a zip chunk does not decompress to " + std::to_string(numBytes) + " bytes");
}

}  // namespace io
}  // namespace OPENVDB_VERSION_NAME
}  // namespace openvdb
