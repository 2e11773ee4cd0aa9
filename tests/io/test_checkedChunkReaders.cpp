#include <array>
#include <cstdint>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <openvdb/Exceptions.h>
#include <openvdb/io/Compression.h>

namespace solidtex {
namespace {

// A chunk whose size field says `size`, followed by `bytes` bytes of 0x41.
std::string chunk(std::int64_t size, std::size_t bytes) {
  std::string stream(reinterpret_cast<const char*>(&size), sizeof size);
  return stream + std::string(bytes, 'A');
}

// OpenVDB 10.0's own readers copy an uncompressed chunk of the size the file claims into the
// node's buffer before comparing it with the buffer's size: these are the checked replacements
// (voxel/detail/checkedChunkReaders.cpp), which must be the ones the dynamic linker chose.
TEST(CheckedChunkReaders, AnUncompressedChunkLongerThanItsBufferIsRefusedBeforeReading) {
  for (auto reader : {&openvdb::io::bloscFromStream, &openvdb::io::unzipFromStream}) {
    std::istringstream in(chunk(-32, 32));
    std::array<char, 48> buffer{};
    EXPECT_THROW(reader(in, buffer.data(), 16), openvdb::RuntimeError);
    EXPECT_EQ(std::string(buffer.data() + 16, 32), std::string(32, '\0')) << "bytes written past the buffer";
  }
}

TEST(CheckedChunkReaders, ACompressedChunkLargerThanItsBoundIsRefusedBeforeAllocating) {
  for (auto reader : {&openvdb::io::bloscFromStream, &openvdb::io::unzipFromStream}) {
    std::istringstream in(chunk(std::int64_t(1) << 60, 64));
    std::array<char, 16> buffer{};
    EXPECT_THROW(reader(in, buffer.data(), buffer.size()), openvdb::RuntimeError);
  }
}

TEST(CheckedChunkReaders, ABloscChunkShorterThanItsHeaderIsRefused) {
  std::istringstream in(chunk(8, 8));
  std::array<char, 64> buffer{};
  EXPECT_THROW(openvdb::io::bloscFromStream(in, buffer.data(), buffer.size()), openvdb::RuntimeError);
}

TEST(CheckedChunkReaders, ChunksTheirWritersMakeReadBack) {
  std::array<float, 300> values{};
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = float(i % 7);
  const char* bytes = reinterpret_cast<const char*>(values.data());
  for (bool blosc : {true, false}) {
    std::ostringstream out;
    if (blosc)
      openvdb::io::bloscToStream(out, bytes, sizeof(float), values.size());
    else
      openvdb::io::zipToStream(out, bytes, sizeof values);
    std::istringstream in(out.str() + chunk(-std::int64_t(sizeof values), sizeof values));
    std::array<float, 300> read{};
    auto reader = blosc ? &openvdb::io::bloscFromStream : &openvdb::io::unzipFromStream;
    reader(in, reinterpret_cast<char*>(read.data()), sizeof read);
    EXPECT_EQ(read, values);
    reader(in, reinterpret_cast<char*>(read.data()), sizeof read);  // stored uncompressed
    EXPECT_EQ(std::string(reinterpret_cast<const char*>(read.data()), sizeof read),
              std::string(sizeof read, 'A'));
  }
}

}  // namespace
}  // namespace solidtex
