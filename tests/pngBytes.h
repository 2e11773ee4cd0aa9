#pragma once
/// @file pngBytes.h
/// @brief PNG files byte by byte, for tests that need broken or exotic ones.
#include <cstdint>
#include <vector>

namespace solidtex::test {

using Bytes = std::vector<unsigned char>;

inline void putU32(Bytes& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back((unsigned char)((v >> shift) & 0xff));
}

/// A chunk: length, type, body and the CRC-32 of type and body.
inline void putChunk(Bytes& out, const char* type, const Bytes& body) {
  putU32(out, std::uint32_t(body.size()));
  Bytes typed(type, type + 4);
  typed.insert(typed.end(), body.begin(), body.end());
  out.insert(out.end(), typed.begin(), typed.end());
  std::uint32_t crc = 0xffffffffu;
  for (unsigned char c : typed) {
    crc ^= c;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  putU32(out, ~crc);
}

/// An 8-bit PNG of one colour (`pixel` of 3 or 4 bytes), stored uncompressed (at most 65535 bytes
/// of rows); `claimedWidth`/`claimedHeight` other than 0 make the header promise other sides.
inline Bytes flatPng(int width, int height, const Bytes& pixel, int claimedWidth = 0, int claimedHeight = 0) {
  Bytes raw;
  for (int y = 0; y < height; ++y) {
    raw.push_back(0);
    for (int x = 0; x < width; ++x) raw.insert(raw.end(), pixel.begin(), pixel.end());
  }
  const auto n = std::uint16_t(raw.size());
  Bytes zlib = {0x78,
                0x01,
                0x01,
                (unsigned char)n,
                (unsigned char)(n >> 8),
                (unsigned char)~n,
                (unsigned char)(std::uint16_t(~n) >> 8)};
  zlib.insert(zlib.end(), raw.begin(), raw.end());
  std::uint32_t a = 1, b = 0;
  for (unsigned char c : raw) a = (a + c) % 65521, b = (b + a) % 65521;
  putU32(zlib, (b << 16) | a);
  Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  Bytes header;
  putU32(header, std::uint32_t(claimedWidth ? claimedWidth : width));
  putU32(header, std::uint32_t(claimedHeight ? claimedHeight : height));
  header.insert(header.end(), {8, (unsigned char)(pixel.size() == 4 ? 6 : 2), 0, 0, 0});
  putChunk(png, "IHDR", header);
  putChunk(png, "IDAT", zlib);
  putChunk(png, "IEND", {});
  return png;
}

}  // namespace solidtex::test
