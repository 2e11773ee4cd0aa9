#include "common/squaredDistanceTransform.h"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace solidtex {
namespace {

// Transforms the lines along x: contiguous, one at a time.
void transformRows(std::vector<std::uint32_t>& f, std::size_t rows, int length) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows), [&](const tbb::blocked_range<std::size_t>& r) {
    LowerEnvelope envelope(length);
    for (std::size_t row = r.begin(); row != r.end(); ++row)
      transformLine(f.data() + row * std::size_t(length), length, 1, envelope);
  });
}

// Transforms the lines `stride` apart (along y or z) in tiles of kTile lines neighbouring in x,
// copied to a buffer a tile row at a time: reading them one by one would take a cache line per
// sample. Lines start at base(group) + i for i < width (the x extent) of each group.
constexpr std::size_t kTile = 16;

template <class GroupBase>
void transformColumns(std::vector<std::uint32_t>& f, std::size_t groups, std::size_t width, int length,
                      std::size_t stride, GroupBase base) {
  const std::size_t tilesPerGroup = (width + kTile - 1) / kTile;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, groups * tilesPerGroup),
      [&](const tbb::blocked_range<std::size_t>& r) {
        LowerEnvelope envelope(length);
        std::vector<std::uint32_t> tile(std::size_t(length) * kTile);
        for (std::size_t t = r.begin(); t != r.end(); ++t) {
          const std::size_t x0 = (t % tilesPerGroup) * kTile, w = std::min(kTile, width - x0);
          std::uint32_t* start = f.data() + base(t / tilesPerGroup) + x0;
          for (int q = 0; q < length; ++q)
            std::copy_n(start + std::size_t(q) * stride, w, tile.data() + std::size_t(q) * kTile);
          for (std::size_t i = 0; i < w; ++i) transformLine(tile.data() + i, length, kTile, envelope);
          for (int q = 0; q < length; ++q)
            std::copy_n(tile.data() + std::size_t(q) * kTile, w, start + std::size_t(q) * stride);
        }
      });
}

}  // namespace

std::vector<std::uint32_t> squaredDistanceToSites(const Dims& dims, const std::vector<std::uint8_t>& isSite) {
  std::vector<std::uint32_t> f;
  squaredDistanceToSites(dims, isSite, f);
  return f;
}

void squaredDistanceToSites(const Dims& dims, const std::vector<std::uint8_t>& isSite,
                            std::vector<std::uint32_t>& f) {
  f.resize(dims.count());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, f.size()),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) f[i] = isSite[i] ? 0 : kNoSite;
                    });
  const std::size_t nx = std::size_t(dims.x), ny = std::size_t(dims.y), plane = nx * ny;
  transformRows(f, ny * std::size_t(dims.z), dims.x);
  transformColumns(f, std::size_t(dims.z), nx, dims.y, nx, [&](std::size_t k) { return k * plane; });
  if (dims.z > 1) transformColumns(f, ny, nx, dims.z, plane, [&](std::size_t j) { return j * nx; });
}

}  // namespace solidtex
