#include "synthesis/detail/SliceNeighborhoods.h"

namespace solidtex::synthesis::detail {

void gatherSliceNeighborhood(const WorkVolume& volume, int axis, const std::array<int, 3>& c,
                             const NeighborhoodShape& shape, float* out) {
  const SliceAxes s = sliceAxes(axis);
  std::array<int, 3> p = c;
  if (!shape.wavelet) {
    for (int j = shape.lo(); j <= shape.hi(); ++j) {
      p[s.w] = volume.wrap(c[s.w] + j);
      for (int i = shape.lo(); i <= shape.hi(); ++i) {
        p[s.u] = volume.wrap(c[s.u] + i);
        const float* v = volume.at(volume.index(p[0], p[1], p[2]));
        *out++ = v[0];
        *out++ = v[1];
        *out++ = v[2];
      }
    }
    return;
  }
  const auto at = [&](int i, int j) {
    p[s.u] = volume.wrap(c[s.u] + i);
    p[s.w] = volume.wrap(c[s.w] + j);
    return volume.at(volume.index(p[0], p[1], p[2]));
  };
  for (int j = shape.lo(); j <= shape.hi(); ++j)
    for (int i = shape.lo(); i <= shape.hi(); ++i)
      writePixelFeatures(shape, at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1), out);
}

}  // namespace solidtex::synthesis::detail
