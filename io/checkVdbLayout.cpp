#include "io/checkVdbLayout.h"

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

  std::string string(const char* what) {
    const auto length = value<std::uint32_t>(what);
    if (length > 1024) fail(std::string("damaged ") + what);
    std::string text(length, '\0');
    if (length > remaining() || !in_.read(text.data(), length)) fail(std::string("truncated in its ") + what);
    return text;
  }

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

// Bytes a map of this type reads after its name (math/Maps.h); 0 for one whose size is not fixed.
std::uint64_t mapBytes(const std::string& type) {
  if (type == "AffineMap" || type == "UnitaryMap") return 16 * 8;      // a Mat4d
  if (type == "ScaleMap" || type == "UniformScaleMap") return 5 * 24;  // five Vec3d
  if (type == "ScaleTranslateMap" || type == "UniformScaleTranslateMap") return 6 * 24;
  if (type == "TranslationMap") return 24;
  return 0;
}

// Bytes of one value of a standard tree type ("Tree_float_5_4_3", also with "_HalfFloat"); 0 for
// another: the child bound below assumes the 5-4-3 configuration's 32768-bit masks.
std::uint64_t valueBytes(const std::string& treeType) {
  const std::pair<const char*, std::uint64_t> sizes[] = {{"float", 4},  {"int32", 4}, {"vec3s", 12},
                                                         {"double", 8}, {"int64", 8}, {"vec3d", 24},
                                                         {"vec3i", 12}, {"bool", 1}};
  for (const auto& [value, bytes] : sizes)
    if (treeType.rfind(std::string("Tree_") + value + "_5_4_3", 0) == 0) return bytes;
  return 0;
}

// The root node's tiles, each (origin, value, active flag): OpenVDB reads the flag's byte into a
// bool, which must then be 0 or 1.
long checkRootTiles(Reader& file, std::uint64_t valueSize, const std::string& grid) {
  file.skip(4 + valueSize, "tree");  // buffer count, background
  const auto tiles = file.value<std::uint32_t>("tree");
  const auto children = file.value<std::uint32_t>("tree");
  const std::uint64_t tileBytes = 12 + valueSize + 1;
  if (tiles > file.remaining() / tileBytes) file.fail(grid + " has more tiles than bytes");
  // A child is at least its origin and two 32768-bit masks; OpenVDB allocates each (0.5 MB or
  // more) before reading it, also past the end of the file.
  if (children > (file.remaining() - tiles * tileBytes) / (12 + 2 * 4096))
    file.fail(grid + " has more nodes than bytes");
  for (std::uint32_t t = 0; t < tiles; ++t) {
    file.skip(12 + valueSize, "tree");
    if (file.value<std::uint8_t>("tree") > 1) file.fail(grid + " has a damaged tile");
  }
  return long(tiles);
}

}  // namespace

std::vector<long> checkVdbLayout(const std::string& path) {
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
  std::vector<long> rootTiles;
  if (!hasOffsets) return rootTiles;  // a streamed file: its grids follow one another without offsets
  const auto grids = file.value<std::int32_t>("grid count");
  if (grids < 0 || grids > kMostGrids) file.fail("damaged grid count");
  for (std::int32_t g = 0; g < grids; ++g) {
    file.skipString("grid descriptor");
    const std::string treeType = file.string("grid descriptor");
    const bool instance = version >= kFirstVersionWithInstancing && !file.string("grid descriptor").empty();
    const auto start = file.value<std::int64_t>("grid descriptor");
    file.value<std::int64_t>("grid descriptor");  // the data block's offset, 0 for an instance
    const auto end = file.value<std::int64_t>("grid descriptor");
    const std::string grid = "grid " + std::to_string(g + 1) + " of " + std::to_string(grids);
    if (start < 0 || end < start || std::uint64_t(end) > file.size())
      file.fail(grid + " runs past the end of the file");
    file.seek(start, "grid offsets");
    file.skip(4, "grid");  // compression flags
    file.skipMetadata("grid metadata");
    // From format 223 the transform follows, its map's type name first (OpenVDB allocates what
    // the name's length claims).
    rootTiles.push_back(-1);
    if (version >= kFirstVersionWithInstancing) {
      const std::uint64_t transform = mapBytes(file.string("grid transform"));
      if (transform > 0 && !instance && valueBytes(treeType) > 0) {
        file.skip(transform, "grid transform");
        rootTiles.back() = checkRootTiles(file, valueBytes(treeType), grid);
      }
    }
    file.seek(end, "grid offsets");
  }
  return rootTiles;
}

}  // namespace solidtex
