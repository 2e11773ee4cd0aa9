#include "validation/chordLengths.h"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace solidtex {
namespace {

using Counts = std::vector<std::size_t>;

Counts add(Counts a, const Counts& b) {
  for (std::size_t i = 0; i < a.size(); ++i) a[i] += b[i];
  return a;
}

// The runs along axis a of the lines through the plane of voxels with coordinate a = 0.
Counts runsAlong(const PhaseField& phase, int a, bool keepCut) {
  const Dims& d = phase.dims;
  const std::array<int, 3> n{d.x, d.y, d.z};
  const std::array<std::size_t, 3> stride{1, std::size_t(d.x), std::size_t(d.x) * std::size_t(d.y)};
  const int u = a == 0 ? 1 : 0, v = a == 2 ? 1 : 2;  // the two other axes
  const std::size_t lines = std::size_t(n[u]) * std::size_t(n[v]);
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, lines), Counts(std::size_t(n[a]) + 1, 0),
      [&](const tbb::blocked_range<std::size_t>& r, Counts acc) {
        for (std::size_t line = r.begin(); line != r.end(); ++line) {
          const std::size_t start =
              (line % std::size_t(n[u])) * stride[u] + (line / std::size_t(n[u])) * stride[v];
          int run = 0;
          bool cut = true;  // the run began at the field's face
          for (int t = 0; t <= n[a]; ++t) {
            const bool in = t < n[a] && phase.inside[start + std::size_t(t) * stride[a]];
            if (in) {
              ++run;
              continue;
            }
            if (run > 0 && (keepCut || (!cut && t < n[a]))) ++acc[std::size_t(run)];
            run = 0;
            cut = false;
          }
        }
        return acc;
      },
      add);
}

}  // namespace

ChordLengths chordLengths(const PhaseField& phase, bool keepCut) {
  ChordLengths out;
  const std::array<int, 3> n{phase.dims.x, phase.dims.y, phase.dims.z};
  for (int a = 0; a < 3; ++a)
    if (n[a] > 1) out.counts[std::size_t(a)] = runsAlong(phase, a, keepCut);
  return out;
}

double meanChord(const std::vector<std::size_t>& counts) {
  double chords = 0, length = 0;
  for (std::size_t l = 1; l < counts.size(); ++l) {
    chords += double(counts[l]);
    length += double(counts[l]) * double(l);
  }
  return chords > 0 ? length / chords : 0.0;
}

std::vector<double> chordHistogram(const std::vector<std::size_t>& counts, int width, int bins) {
  std::vector<double> share(std::size_t(std::max(bins, 1)), 0.0);
  double total = 0;
  for (std::size_t l = 1; l < counts.size(); ++l) {
    const std::size_t bin = std::min((l - 1) / std::size_t(std::max(width, 1)), share.size() - 1);
    share[bin] += double(counts[l]);
    total += double(counts[l]);
  }
  if (total > 0)
    for (double& s : share) s /= total;
  return share;
}

}  // namespace solidtex
