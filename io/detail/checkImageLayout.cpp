#include "io/detail/checkImageLayout.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>

namespace solidtex::io::detail {
namespace {

std::string pngProblem(std::ifstream& in, std::uint64_t size) {
  for (std::uint64_t at = 8; at + 12 <= size;) {
    unsigned char header[8] = {};
    if (!in.read(reinterpret_cast<char*>(header), 8)) return "";
    const std::uint64_t length =
        (std::uint64_t(header[0]) << 24) | (header[1] << 16) | (header[2] << 8) | header[3];
    if (at + 12 + length > size) return "a PNG chunk runs past the end of the file";
    if (std::equal(header + 4, header + 8, "IEND")) return "";
    at += 12 + length;
    in.seekg(std::streamoff(at));
  }
  return "";
}

// A null-terminated name of at most 255 characters; false at the end of the file.
bool readName(std::ifstream& in, std::string& name) {
  name.clear();
  for (char c; in.get(c);) {
    if (c == '\0') return true;
    if (name.size() == 255) return false;
    name += c;
  }
  return false;
}

// Header attributes are (name, type, 32-bit size, value), a header ends with an empty name, and a
// multi-part file's headers end with an empty header.
std::string exrProblem(std::ifstream& in, std::uint64_t size, bool multipart) {
  const std::string truncated = "an OpenEXR header attribute runs past the end of the file";
  std::string name, type;
  for (bool headerEmpty = true;;) {
    if (!readName(in, name)) return truncated;
    if (name.empty()) {
      if (!multipart || headerEmpty) return "";
      headerEmpty = true;
      continue;
    }
    headerEmpty = false;
    unsigned char length[4] = {};
    if (!readName(in, type) || !in.read(reinterpret_cast<char*>(length), 4)) return truncated;
    const std::uint64_t bytes =
        length[0] | (length[1] << 8) | (length[2] << 16) | (std::uint64_t(length[3]) << 24);
    const auto at = std::uint64_t(in.tellg());
    if (at + bytes > size) return truncated;
    in.seekg(std::streamoff(at + bytes));
  }
}

}  // namespace

std::string imageLayoutProblem(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char magic[8] = {};
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (ec || !in.read(reinterpret_cast<char*>(magic), 8)) return "";
  const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (std::equal(magic, magic + 8, png)) return pngProblem(in, size);
  const unsigned char exr[4] = {0x76, 0x2f, 0x31, 0x01};
  if (std::equal(magic, magic + 4, exr)) return exrProblem(in, size, (magic[5] & 0x10) != 0);
  return "";
}

}  // namespace solidtex::io::detail
