#include "common/squaredDistanceTransform.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace solidtex {
namespace {

// Transforms `lines` lines of `length` samples `stride` apart, line l starting at start(l).
template <class LineStart>
void transformLines(std::vector<std::uint32_t>& f, std::size_t lines, int length, std::ptrdiff_t stride,
                    LineStart start) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, lines), [&](const tbb::blocked_range<std::size_t>& r) {
    LowerEnvelope envelope(length);
    for (std::size_t line = r.begin(); line != r.end(); ++line)
      transformLine(f.data() + start(line), length, stride, envelope);
  });
}

}  // namespace

std::vector<std::uint32_t> squaredDistanceToSites(const Dims& dims, const std::vector<std::uint8_t>& isSite) {
  std::vector<std::uint32_t> f(dims.count());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = isSite[i] ? 0 : kNoSite;
  const std::size_t nx = std::size_t(dims.x), ny = std::size_t(dims.y), plane = nx * ny;
  transformLines(f, ny * std::size_t(dims.z), dims.x, 1, [&](std::size_t l) { return l * nx; });
  transformLines(f, nx * std::size_t(dims.z), dims.y, std::ptrdiff_t(nx),
                 [&](std::size_t l) { return (l / nx) * plane + l % nx; });
  if (dims.z > 1) transformLines(f, plane, dims.z, std::ptrdiff_t(plane), [](std::size_t l) { return l; });
  return f;
}

}  // namespace solidtex
