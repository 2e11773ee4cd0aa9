#include "voxel/checkVdbLayout.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "common/Error.h"

namespace solidtex {
namespace {

// OpenVDB's layout (io/Archive, io/GridDescriptor): magic, versions, grid-offsets flag, UUID; the
// file's metadata (count, then name, type, byte count and value each); the grid count, then per
// grid its name, type and instance parent, and the offsets of its data, the next descriptor
// starting at the grid's end.
// Format 222 (OpenVDB 3.0, 2014) gave each grid its compression flags; older files are refused
// rather than left unchecked to OpenVDB.
constexpr std::uint32_t kOldestVersion = 222;
constexpr std::uint32_t kFirstVersionWithInstancing = 223;
constexpr std::int32_t kMostGrids = 1 << 16;

class Reader {
public:
  Reader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    std::error_code ec;
    size_ = std::filesystem::file_size(path, ec);
    if (!in_ || ec) fail("cannot open it");
  }

  [[noreturn]] void fail(const std::string& why) const {
    throw InputError("cannot read " + path_ + ": not a readable OpenVDB file (" + why + ")");
  }

  std::uint64_t remaining() { return size_ - std::uint64_t(in_.tellg()); }

  template <typename T>
  T value(const char* what) {
    T v{};
    if (remaining() < sizeof v || !in_.read(reinterpret_cast<char*>(&v), sizeof v))
      fail(std::string("truncated in its ") + what);
    return v;
  }

  void skip(std::uint64_t bytes, const char* what) {
    if (bytes > remaining()) fail(std::string("truncated or damaged in its ") + what);
    in_.seekg(std::streamoff(bytes), std::ios::cur);
  }

  void skipString(const char* what) { skip(value<std::uint32_t>(what), what); }

  // A metadata map: its count, then name, type and a byte count with the value, each.
  void skipMetadata(const char* what) {
    const auto count = value<std::int32_t>(what);
    if (count < 0) fail(std::string("damaged ") + what);
    for (std::int32_t i = 0; i < count; ++i)
      for (int field = 0; field < 3; ++field) skipString(what);
  }

  void seek(std::int64_t position, const char* what) {
    if (position < 0 || std::uint64_t(position) > size_) fail(std::string("damaged ") + what);
    in_.seekg(position);
  }

  std::uint64_t size() const { return size_; }

private:
  std::string path_;
  std::ifstream in_;
  std::uint64_t size_ = 0;
};

}  // namespace

void checkVdbLayout(const std::string& path) {
  Reader file(path);
  if (file.value<std::int64_t>("header") != 0x56444220) file.fail("no OpenVDB header");
  const auto version = file.value<std::uint32_t>("header");
  if (version < kOldestVersion)
    file.fail("file format " + std::to_string(version) +
              " is older than OpenVDB 3.0's; save it again with a newer OpenVDB");
  file.skip(8, "header");  // library version
  const bool hasOffsets = file.value<char>("header") != 0;
  file.skip(36, "header");  // UUID
  file.skipMetadata("metadata");
  if (!hasOffsets) return;  // a streamed file: its grids follow one another without offsets
  const auto grids = file.value<std::int32_t>("grid count");
  if (grids < 0 || grids > kMostGrids) file.fail("damaged grid count");
  for (std::int32_t g = 0; g < grids; ++g) {
    file.skipString("grid descriptor");
    file.skipString("grid descriptor");
    if (version >= kFirstVersionWithInstancing) file.skipString("grid descriptor");
    const auto start = file.value<std::int64_t>("grid descriptor");
    file.value<std::int64_t>("grid descriptor");  // the data block's offset, 0 for an instance
    const auto end = file.value<std::int64_t>("grid descriptor");
    if (start < 0 || end < start || std::uint64_t(end) > file.size())
      file.fail("grid " + std::to_string(g + 1) + " of " + std::to_string(grids) +
                " runs past the end of the file");
    file.seek(start, "grid offsets");
    file.skip(4, "grid");  // compression flags
    file.skipMetadata("grid metadata");
    file.seek(end, "grid offsets");
  }
}

}  // namespace solidtex
