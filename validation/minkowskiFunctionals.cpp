#include "validation/minkowskiFunctionals.h"

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace solidtex {
namespace {

using Axes = std::array<int, 3>;

// A cell of the voxels' cubical complex, named by the axes along which it touches two voxels: a
// cell at lattice position p touches the voxels p - span .. p. {1,1,1} is a vertex, {0,0,0} a voxel.
using Span = Axes;

bool voxelAt(const PhaseField& phase, int i, int j, int k) {
  return phase.dims.contains(i, j, k) && phase.inside[phase.dims.index(i, j, k)];
}

// How many cells of `span` are in the complex (any touched voxel in the phase when closed, all when
// open), over the positions from lo to hi (inclusive) per axis.
std::size_t cellsPresent(const PhaseField& phase, const Span& span, const Axes& lo, const Axes& hi,
                         bool closed) {
  if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]) return 0;
  return tbb::parallel_reduce(
      tbb::blocked_range<int>(lo[2], hi[2] + 1), std::size_t(0),
      [&](const tbb::blocked_range<int>& ks, std::size_t acc) {
        for (int k = ks.begin(); k != ks.end(); ++k)
          for (int j = lo[1]; j <= hi[1]; ++j)
            for (int i = lo[0]; i <= hi[0]; ++i) {
              int in = 0, touched = 0;
              for (int dz = 0; dz <= span[2]; ++dz)
                for (int dy = 0; dy <= span[1]; ++dy)
                  for (int dx = 0; dx <= span[0]; ++dx) {
                    in += voxelAt(phase, i - dx, j - dy, k - dz);
                    ++touched;
                  }
              acc += closed ? in > 0 : in == touched;
            }
        return acc;
      },
      std::plus<>());
}

Axes extentOf(const PhaseField& phase) { return {phase.dims.x, phase.dims.y, phase.dims.z}; }

// The spans of the complex's cells: over x, y and z in 3D, over x and y in an image.
std::vector<Span> spansOf(const PhaseField& phase) {
  std::vector<Span> spans;
  const int zs = phase.isImage() ? 1 : 2;
  for (int z = 0; z < zs; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) spans.push_back({x, y, z});
  return spans;
}

int dimensionOf(const PhaseField& phase, const Span& span) {
  return (phase.isImage() ? 2 : 3) - span[0] - span[1] - span[2];
}

bool voxelWrapped(const PhaseField& phase, int i, int j, int k) {
  return phase.inside[phase.dims.index(phase.dims.wrap({i, j, k}))];
}

// Where a lattice position lies along an axis: on the first layer, inside, or on the last.
int layerClass(int p, int n) { return p == 0 ? 0 : p == n - 1 ? 2 : 1; }

// The closed complex's cells counted once for every window the densities use: per span (indexed
// x + 2y + 4z) and per layer class of the position along each axis, in one pass over the field.
struct CellCounts {
  std::array<std::array<double, 27>, 8> bySpanAndClass{};
};

CellCounts countCells(const PhaseField& phase, bool periodic) {
  const Axes n = extentOf(phase);
  const int spans = phase.isImage() ? 4 : 8;
  const auto at = [&](int i, int j, int k) {
    if (periodic) return voxelWrapped(phase, i, j, k);
    return phase.dims.contains(i, j, k) && phase.inside[phase.dims.index(i, j, k)] != 0;
  };
  using Counts = std::array<std::array<double, 27>, 8>;
  const Counts counts = tbb::parallel_reduce(
      tbb::blocked_range<int>(0, n[2]), Counts{},
      [&](const tbb::blocked_range<int>& ks, Counts acc) {
        for (int k = ks.begin(); k != ks.end(); ++k)
          for (int j = 0; j < n[1]; ++j)
            for (int i = 0; i < n[0]; ++i) {
              std::array<bool, 8> voxel{};  // p - d for d in {0,1}^3, indexed dx + 2dy + 4dz
              for (int d = 0; d < spans; ++d)
                voxel[std::size_t(d)] = at(i - (d & 1), j - ((d >> 1) & 1), k - (d >> 2));
              const int cls = layerClass(i, n[0]) + 3 * layerClass(j, n[1]) + 9 * layerClass(k, n[2]);
              for (int span = 0; span < spans; ++span) {
                const bool inside = periodic || ((!(span & 1) || i >= 1) && (!(span & 2) || j >= 1) &&
                                                 (!(span & 4) || k >= 1));
                if (!inside) continue;
                bool present = false;
                for (int d = 0; d < spans && !present; ++d)
                  present = (d & ~span) == 0 && voxel[std::size_t(d)];
                if (present) acc[std::size_t(span)][std::size_t(cls)] += 1;
              }
            }
        return acc;
      },
      [](Counts a, const Counts& b) {
        for (std::size_t s = 0; s < 8; ++s)
          for (std::size_t c = 0; c < 27; ++c) a[s][c] += b[s][c];
        return a;
      });
  return {counts};
}

// The density per voxel of the closed complex's cells of `span`, counted in the 2x2(x2) windows of
// voxels along `window` (the other axes are sampled plane by plane): a cell counts by the share of
// the windows that hold it which lie in the field, so that every window sees all of its cells and
// an object inside the field counts exactly. Periodic: the windows wrap around.
double cellDensity(const PhaseField& phase, const CellCounts& counts, const Span& span, const Axes& window,
                   bool periodic) {
  const Axes n = extentOf(phase);
  double windows = 1;
  for (int a = 0; a < 3; ++a) windows *= periodic || !window[a] ? n[a] : n[a] - 1;
  if (windows <= 0) return 0;
  const auto weightOf = [&](int a, int cls) {
    if (periodic || !window[a] || span[a]) return 1.0;
    const int p = cls == 0 ? 0 : cls == 2 ? n[a] - 1 : 1;
    return 0.5 * ((p >= 1) + (p <= n[a] - 2));
  };
  double cells = 0;
  const auto& bySpan = counts.bySpanAndClass[std::size_t(span[0] + 2 * span[1] + 4 * span[2])];
  for (int c = 0; c < 27; ++c)
    cells += bySpan[std::size_t(c)] * weightOf(0, c % 3) * weightOf(1, (c / 3) % 3) * weightOf(2, c / 9);
  return cells / windows;
}

// The Euler characteristic per voxel (per pixel of the planes across `normal`, or of the image
// when normal < 0) of the closed complex: the alternating sum of its cells' densities.
double eulerDensity(const PhaseField& phase, const CellCounts& counts, int normal, bool periodic) {
  Axes window{1, 1, phase.isImage() ? 0 : 1};
  if (normal >= 0) window[std::size_t(normal)] = 0;
  const int dimension = window[0] + window[1] + window[2];
  double chi = 0;
  for (const Span& span : spansOf(phase)) {
    if ((span[0] && !window[0]) || (span[1] && !window[1]) || (span[2] && !window[2])) continue;
    const int cellDimension = dimension - span[0] - span[1] - span[2];
    chi += (cellDimension % 2 == 0 ? 1 : -1) * cellDensity(phase, counts, span, window, periodic);
  }
  return chi;
}

// Line directions of the lattice and the share of the unit sphere (circle) nearest to each: the
// weights of a Crofton estimate for isotropic lines, found once by a Fibonacci lattice of points.
struct CroftonDirections {
  std::vector<Axes> steps;
  std::vector<double> weights;
};

CroftonDirections croftonDirections(bool image) {
  CroftonDirections d;
  if (image) {
    d.steps = {{1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, -1, 0}};
    d.weights.assign(4, 0.25);  // 8 directions 45 degrees apart share the circle alike
    return d;
  }
  d.steps = {{1, 0, 0}, {0, 1, 0},  {0, 0, 1}, {1, 1, 0},  {1, -1, 0}, {1, 0, 1},  {1, 0, -1},
             {0, 1, 1}, {0, 1, -1}, {1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {1, -1, -1}};
  d.weights.assign(d.steps.size(), 0.0);
  constexpr int kPoints = 200000;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int p = 0; p < kPoints; ++p) {
    const double z = 1.0 - (2.0 * p + 1.0) / kPoints, rho = std::sqrt(1.0 - z * z);
    const double x = rho * std::cos(golden * p), y = rho * std::sin(golden * p);
    std::size_t nearest = 0;
    double best = -1;
    for (std::size_t s = 0; s < d.steps.size(); ++s) {
      const Axes& v = d.steps[s];
      const double c = std::abs(x * v[0] + y * v[1] + z * v[2]) /
                       std::sqrt(double(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
      if (c > best) best = c, nearest = s;
    }
    d.weights[nearest] += 1.0 / kPoints;
  }
  return d;
}

// Entries and exits of the phase per unit length along lines of direction `step`.
double crossingsPerLength(const PhaseField& phase, const Axes& step, bool periodic) {
  const Axes n = extentOf(phase);
  Axes lo{}, hi{};
  double pairs = 1;
  for (int a = 0; a < 3; ++a) {
    lo[a] = periodic ? 0 : std::max(0, -step[a]);
    hi[a] = n[a] - 1 - (periodic ? 0 : std::max(0, step[a]));
    pairs *= hi[a] - lo[a] + 1;
  }
  if (pairs <= 0) return 0;
  const std::size_t crossings = tbb::parallel_reduce(
      tbb::blocked_range<int>(lo[2], hi[2] + 1), std::size_t(0),
      [&](const tbb::blocked_range<int>& ks, std::size_t acc) {
        for (int k = ks.begin(); k != ks.end(); ++k)
          for (int j = lo[1]; j <= hi[1]; ++j)
            for (int i = lo[0]; i <= hi[0]; ++i)
              acc += phase.inside[phase.dims.index(i, j, k)] !=
                     (periodic ? voxelWrapped(phase, i + step[0], j + step[1], k + step[2])
                               : phase.inside[phase.dims.index(i + step[0], j + step[1], k + step[2])] != 0);
        return acc;
      },
      std::plus<>());
  const double length = std::sqrt(double(step[0] * step[0] + step[1] * step[1] + step[2] * step[2]));
  return double(crossings) / (pairs * length);
}

}  // namespace

std::int64_t eulerCharacteristic(const PhaseField& phase, Connectivity connectivity) {
  const Axes n = extentOf(phase);
  std::int64_t chi = 0;
  for (const Span& span : spansOf(phase)) {
    const Axes lo{0, 0, 0}, hi{n[0] - 1 + span[0], n[1] - 1 + span[1], n[2] - 1 + span[2]};
    const auto cells =
        std::int64_t(cellsPresent(phase, span, lo, hi, connectivity == Connectivity::Vertices));
    chi += dimensionOf(phase, span) % 2 == 0 ? cells : -cells;
  }
  // Open cells give the Euler characteristic with compact support: (-1)^dimension times the set's.
  return connectivity == Connectivity::Faces && !phase.isImage() ? -chi : chi;
}

MinkowskiDensities minkowskiDensities(const PhaseField& phase, bool periodic) {
  MinkowskiDensities out;
  out.fraction = phase.fraction();
  const CroftonDirections directions = croftonDirections(phase.isImage());
  double meanCrossings = 0;
  for (std::size_t s = 0; s < directions.steps.size(); ++s)
    meanCrossings += directions.weights[s] * crossingsPerLength(phase, directions.steps[s], periodic);
  out.boundary = phase.isImage() ? std::numbers::pi / 2 * meanCrossings : 2 * meanCrossings;
  const CellCounts cells = countCells(phase, periodic);
  out.euler = eulerDensity(phase, cells, -1, periodic);
  if (phase.isImage()) return out;
  const double sections = eulerDensity(phase, cells, 0, periodic) + eulerDensity(phase, cells, 1, periodic) +
                          eulerDensity(phase, cells, 2, periodic);
  out.meanCurvature = 2 * std::numbers::pi * sections / 3;
  return out;
}

}  // namespace solidtex
