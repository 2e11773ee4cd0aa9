#include "particles/voxelizeHull.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace solidtex {
namespace {

// Vertices snap to 1/65536 voxel: with sides up to kMaxParticleSide every orientation below is an
// exact int64 product (at most 2^61), so shared edges split the rows consistently.
constexpr int kGridBits = 16;
constexpr double kGrid = double(std::int64_t(1) << kGridBits);
constexpr std::int64_t kHalf = 32768;

struct GridPoint {
  std::int64_t x, y, z;
};

// A ray along +x through the centres of voxel row `row` meets the surface at x (voxel units).
struct Crossing {
  double x;
  std::uint32_t row;
  std::int32_t enter;  // +1 into the hull, -1 out of it
};

void checkSides(int w, int h, int d) {
  for (const int side : {w, h, d})
    if (side < 1 || side > kMaxParticleSide)
      throw std::invalid_argument("voxelize: box side " + std::to_string(side) + " is outside [1, " +
                                  std::to_string(kMaxParticleSide) + "]");
}

// Turned, then scaled per axis so that the hull's box is exactly [0,w] x [0,h] x [0,d] (voxel units).
struct BoxFit {
  Eigen::Matrix3d rotation;
  Eigen::Vector3d lo, scale;
  HullPose pose() const { return {-1, scale.asDiagonal() * rotation, -scale.cwiseProduct(lo)}; }
};

// `turned`: the hull's vertices turned by `rotation`.
BoxFit fitInBox(const HullMesh& hull, const std::vector<Eigen::Vector3d>& turned,
                const Eigen::Matrix3d& rotation, const Dims& dims) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Eigen::Vector3d& p : turned) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector3d extent = hi - lo;
  if (hull.triangles.empty() || !extent.allFinite() || extent.minCoeff() <= 0)
    throw std::invalid_argument("voxelize: the hull is empty or flat");
  return {rotation, lo, Eigen::Vector3d(dims.x, dims.y, dims.z).cwiseQuotient(extent)};
}

// The nearest grid step (halves up) without a libm call: every vertex of every shape passes here.
std::int64_t toGrid(double v) {
  const double t = v * kGrid + 0.5;
  const auto truncated = std::int64_t(t);
  return truncated - std::int64_t(t < double(truncated));
}

// Side of the row centre (py,pz) from edge a->b in the (y,z) plane. The centre is nudged by
// (eps, eps^2) for an infinitesimal eps (simulation of simplicity), so it is never on an edge and the
// triangles around it count it exactly once.
int side(const GridPoint& a, const GridPoint& b, std::int64_t py, std::int64_t pz) {
  const std::int64_t dy = b.y - a.y, dz = b.z - a.z;
  const std::int64_t o = dy * (pz - a.z) - dz * (py - a.y);
  if (o != 0) return o > 0 ? 1 : -1;
  if (dz != 0) return dz < 0 ? 1 : -1;
  return dy > 0 ? 1 : -1;
}

// Row centres j + 0.5 within [lo, hi] (grid units), clamped to the box. The arithmetic shifts are
// floor divisions by kGrid.
std::array<int, 2> rowRange(std::int64_t lo, std::int64_t hi, int count) {
  const std::int64_t first = -((kHalf - lo) >> kGridBits);  // ceil((lo - kHalf) / kGrid)
  const std::int64_t last = (hi - kHalf) >> kGridBits;
  return {int(std::max<std::int64_t>(first, 0)), int(std::min<std::int64_t>(last, count - 1))};
}

// Most triangles of a finely meshed hull lie between row centres: they are dropped on their box
// before anything else is computed.
void addCrossings(const GridPoint& a, const GridPoint& b, const GridPoint& c, const Dims& dims,
                  std::vector<Crossing>& out) {
  const auto [j0, j1] = rowRange(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), dims.y);
  if (j0 > j1) return;
  const auto [k0, k1] = rowRange(std::min({a.z, b.z, c.z}), std::max({a.z, b.z, c.z}), dims.z);
  if (k0 > k1) return;
  const std::int64_t normalX = (b.y - a.y) * (c.z - a.z) - (b.z - a.z) * (c.y - a.y);
  if (normalX == 0) return;  // edge-on to every row
  const int orientation = normalX > 0 ? 1 : -1;
  const double ab[3] = {double(b.x - a.x), double(b.y - a.y), double(b.z - a.z)};
  const double ac[3] = {double(c.x - a.x), double(c.y - a.y), double(c.z - a.z)};
  const double normalY = ab[2] * ac[0] - ab[0] * ac[2], normalZ = ab[0] * ac[1] - ab[1] * ac[0];
  for (int k = k0; k <= k1; ++k) {
    const std::int64_t pz = k * std::int64_t(kGrid) + kHalf;
    for (int j = j0; j <= j1; ++j) {
      const std::int64_t py = j * std::int64_t(kGrid) + kHalf;
      if (side(a, b, py, pz) != orientation || side(b, c, py, pz) != orientation ||
          side(c, a, py, pz) != orientation)
        continue;
      const double x =
          double(a.x) - (normalY * double(py - a.y) + normalZ * double(pz - a.z)) / double(normalX);
      out.push_back({x / kGrid, std::uint32_t(k * dims.y + j), -orientation});
    }
  }
}

// Crossings grouped by row (counting sort), each row in x order.
std::vector<Crossing> byRow(const std::vector<Crossing>& crossings, std::vector<std::size_t>& rowStart) {
  std::fill(rowStart.begin(), rowStart.end(), 0);
  for (const Crossing& c : crossings) ++rowStart[c.row + 1];
  std::partial_sum(rowStart.begin(), rowStart.end(), rowStart.begin());
  std::vector<Crossing> sorted(crossings.size());
  std::vector<std::size_t> next(rowStart.begin(), rowStart.end() - 1);
  for (const Crossing& c : crossings) sorted[next[c.row]++] = c;
  for (std::size_t row = 0; row + 1 < rowStart.size(); ++row)
    std::sort(
        sorted.begin() + std::ptrdiff_t(rowStart[row]), sorted.begin() + std::ptrdiff_t(rowStart[row + 1]),
        [](const Crossing& a, const Crossing& b) { return a.x != b.x ? a.x < b.x : a.enter < b.enter; });
  return sorted;
}

// Voxel centres with a positive winding number: the crossings left of a centre add up to it.
std::vector<std::uint8_t> fillRows(const std::vector<Crossing>& crossings, const Dims& dims) {
  std::vector<std::size_t> rowStart(std::size_t(dims.y) * std::size_t(dims.z) + 1);
  const std::vector<Crossing> sorted = byRow(crossings, rowStart);
  std::vector<std::uint8_t> inside(dims.count(), 0);
  for (std::size_t row = 0; row + 1 < rowStart.size(); ++row) {
    std::size_t c = rowStart[row];
    int winding = 0;
    for (int i = 0; i < dims.x && c < rowStart[row + 1]; ++i) {
      for (; c < rowStart[row + 1] && sorted[c].x < i + 0.5; ++c) winding += sorted[c].enter;
      inside[row * std::size_t(dims.x) + std::size_t(i)] = winding > 0;
    }
  }
  return inside;
}

// A run of particle voxels [begin, end) along x in row (j, k).
struct Run {
  int j, k, begin, end;
};

std::vector<Run> runsOf(const VoxelShape& shape) {
  std::vector<Run> runs;
  for (int k = 0; k < shape.dims.z; ++k)
    for (int j = 0; j < shape.dims.y; ++j) {
      const std::uint8_t* row = &shape.inside[shape.dims.index(0, j, k)];
      for (int i = 0; i < shape.dims.x;) {
        if (!row[i]) {
          ++i;
          continue;
        }
        const int begin = i;
        while (i < shape.dims.x && row[i]) ++i;
        runs.push_back({j, k, begin, i});
      }
    }
  return runs;
}

int findRoot(std::vector<int>& parent, int r) {
  while (parent[std::size_t(r)] != r)
    r = parent[std::size_t(r)] = parent[std::size_t(parent[std::size_t(r)])];
  return r;
}

// Joins each run with the overlapping runs of the rows below it in y and in z (6-connectivity).
std::vector<int> joinRuns(const std::vector<Run>& runs, const Dims& dims) {
  std::vector<std::size_t> rowStart(std::size_t(dims.y) * std::size_t(dims.z) + 1, runs.size());
  for (std::size_t r = runs.size(); r-- > 0;)
    rowStart[std::size_t(runs[r].k) * std::size_t(dims.y) + std::size_t(runs[r].j)] = r;
  for (std::size_t row = rowStart.size() - 1; row-- > 0;)
    rowStart[row] = std::min(rowStart[row], rowStart[row + 1]);
  std::vector<int> parent(runs.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const Run& run = runs[r];
    for (const auto& [j, k] : {std::array{run.j - 1, run.k}, std::array{run.j, run.k - 1}}) {
      if (j < 0 || k < 0) continue;
      const std::size_t row = std::size_t(k) * std::size_t(dims.y) + std::size_t(j);
      for (std::size_t q = rowStart[row]; q < rowStart[row + 1]; ++q)
        if (runs[q].begin < run.end && run.begin < runs[q].end)
          parent[std::size_t(findRoot(parent, int(q)))] = findRoot(parent, int(r));
    }
  }
  return parent;
}

// Thin parts can fall apart between voxel centres; the largest 6-connected piece (first on ties) stays.
void keepLargestPiece(VoxelShape& shape) {
  const std::vector<Run> runs = runsOf(shape);
  std::vector<int> parent = joinRuns(runs, shape.dims);
  std::vector<long> size(runs.size(), 0);
  for (std::size_t r = 0; r < runs.size(); ++r)
    size[std::size_t(findRoot(parent, int(r)))] += runs[r].end - runs[r].begin;
  const auto best = int(std::max_element(size.begin(), size.end()) - size.begin());
  for (std::size_t r = 0; r < runs.size(); ++r)
    if (findRoot(parent, int(r)) != best)
      std::fill_n(&shape.inside[shape.dims.index(runs[r].begin, runs[r].j, runs[r].k)],
                  runs[r].end - runs[r].begin, 0);
}

using Coord = std::array<int, 3>;

Coord sizeOf(const Dims& dims) { return {dims.x, dims.y, dims.z}; }

bool isInside(const VoxelShape& shape, const Coord& c) {
  return shape.inside[shape.dims.index(c[0], c[1], c[2])] != 0;
}

// Occupied extent per axis: lo[axis], hi[axis].
std::array<Coord, 2> occupiedBox(const VoxelShape& shape) {
  Coord lo = sizeOf(shape.dims), hi{-1, -1, -1}, c{};
  for (c[2] = 0; c[2] < shape.dims.z; ++c[2])
    for (c[1] = 0; c[1] < shape.dims.y; ++c[1])
      for (c[0] = 0; c[0] < shape.dims.x; ++c[0])
        if (isInside(shape, c))
          for (std::size_t a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], c[a]);
            hi[a] = std::max(hi[a], c[a]);
          }
  return {lo, hi};
}

// The shape cut to its occupied box; one voxel when sampling caught none.
void cropToOccupiedBox(VoxelShape& shape) {
  const auto [lo, hi] = occupiedBox(shape);
  if (hi[0] < 0) {  // the hull's box centred on the voxel
    shape.pose.offset -=
        (Eigen::Vector3d(shape.dims.x, shape.dims.y, shape.dims.z) - Eigen::Vector3d::Ones()) / 2;
    shape.dims = {1, 1, 1};
    shape.inside = {1};
    return;
  }
  const Dims cropped{hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1};
  shape.pose.offset -= Eigen::Vector3d(lo[0], lo[1], lo[2]);
  if (cropped == shape.dims) return;
  std::vector<std::uint8_t> inside(cropped.count());
  for (int k = 0; k < cropped.z; ++k)
    for (int j = 0; j < cropped.y; ++j)
      std::copy_n(&shape.inside[shape.dims.index(lo[0], j + lo[1], k + lo[2])], cropped.x,
                  &inside[cropped.index(0, j, k)]);
  shape.dims = cropped;
  shape.inside = std::move(inside);
}

}  // namespace

HullMesh posedHull(const HullMesh& hull, const HullPose& pose) {
  HullMesh posed = hull;
  for (Eigen::Vector3d& v : posed.vertices) v = pose.linear * v + pose.offset;
  return posed;
}

VoxelShape voxelize(const HullMesh& hull, const Eigen::Matrix3d& rotation, int w, int h, int d) {
  checkSides(w, h, d);
  VoxelShape shape;
  shape.dims = {w, h, d};
  std::vector<Eigen::Vector3d> turned(hull.vertices.size());
  std::transform(hull.vertices.begin(), hull.vertices.end(), turned.begin(),
                 [&](const Eigen::Vector3d& v) -> Eigen::Vector3d { return rotation * v; });
  const BoxFit fit = fitInBox(hull, turned, rotation, shape.dims);
  shape.pose = fit.pose();
  std::vector<GridPoint> grid(turned.size());
  std::transform(turned.begin(), turned.end(), grid.begin(), [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d q = (p - fit.lo).cwiseProduct(fit.scale);
    return GridPoint{toGrid(q.x()), toGrid(q.y()), toGrid(q.z())};
  });
  std::vector<Crossing> crossings;
  crossings.reserve(std::size_t(2) * std::size_t(h) * std::size_t(d));
  for (const auto& [a, b, c] : hull.triangles)
    addCrossings(grid[std::size_t(a)], grid[std::size_t(b)], grid[std::size_t(c)], shape.dims, crossings);
  shape.inside = fillRows(crossings, shape.dims);
  keepLargestPiece(shape);
  cropToOccupiedBox(shape);
  return shape;
}

}  // namespace solidtex
