#include "validation/linealPath.h"

#include <algorithm>

#include "validation/chordLengths.h"

namespace solidtex {

// A run of l voxels holds l - r of the segments of length r; a line of n voxels holds n - r.
std::array<std::vector<double>, 3> linealPath(const PhaseField& phase, int maxDistance) {
  const ChordLengths runs = chordLengths(phase, true);
  const std::array<int, 3> n{phase.dims.x, phase.dims.y, phase.dims.z};
  std::array<std::vector<double>, 3> out;
  for (int a = 0; a < 3; ++a) {
    const auto& counts = runs.counts[std::size_t(a)];
    if (counts.empty()) continue;
    const double lines = double(phase.dims.count()) / n[a];
    const int R = std::min(maxDistance, n[a] - 1);
    for (int r = 0; r <= R; ++r) {
      double inside = 0;
      for (std::size_t l = std::size_t(r) + 1; l < counts.size(); ++l)
        inside += double(counts[l]) * double(l - std::size_t(r));
      out[std::size_t(a)].push_back(inside / (lines * (n[a] - r)));
    }
  }
  return out;
}

}  // namespace solidtex
