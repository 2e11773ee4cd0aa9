// Delaunay spaciousness (paper 3.7): a 3D Delaunay triangulation of a sample of the particles'
// boundary voxels and of samples of the walls. Every finite cell's circumsphere is empty, so its
// circumcentre, rounded to a voxel, is a candidate spot; the candidates are bucketed by value and a
// cell's candidate is dropped as soon as an insertion destroys the cell (find_conflicts +
// insert_in_hole tell exactly which cells die). The only CGAL translation unit of placement/.
//
// The sample: every boundary voxel that faces free space when its particle goes in becomes a
// triangulation vertex or is 6-adjacent to one. The voxel nearest to any free voxel faces free
// space (see facesFreeSpace) and did so when it went in, as space only fills; so a ball empty of
// the vertices is empty of the particles once shrunk by one voxel (the field's slack). Voxels with
// x + y + z divisible by 3 are such a sample wherever the surface is locally flat (each of the other
// two residues has a neighbour of residue 0 along every axis); a voxel with no sampled 6-neighbour
// yet (of this particle or an earlier one) joins the sample. That is about 40 % of the boundary
// voxels, and the triangulation's time and memory follow its vertex count.
//
// A periodic volume has no walls. Each sample point goes in with its images across the faces that lie
// within the cap (plus the slack) of the volume, so every empty sphere centred in the volume that
// is no larger than the cap is empty on the torus too: the standard triangulation with these ghost
// points, rather than CGAL's periodic one, which needs a cubic domain and hides the conflict sets
// the candidate queue is kept by. Eight far corners, beyond the cap of every voxel, give the empty
// volume its first cells.
#include <algorithm>
#include <array>
#include <cmath>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_3.h>
#include <CGAL/spatial_sort.h>

#include "placement/SpaciousnessField.h"
#include "placement/detail/VoxelBits.h"
#include "placement/detail/uniformSample.h"
#include "placement/detail/voxelSets.h"

namespace solidtex::placement::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

/// Where a cell's candidate sits in the buckets (bucket 0: it has none), and whether the cell was
/// created during the insertion under way and has not been looked at yet.
struct QueueSlot {
  std::uint32_t bucket = 0;
  std::uint32_t pos = 0;
  bool pending = false;
};

using CellBase = CGAL::Triangulation_cell_base_with_info_3<QueueSlot, Kernel,
                                                           CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<Kernel>, CellBase,
                                                 CGAL::Sequential_tag>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
using Cell = Delaunay::Cell_handle;
using Vertex = Delaunay::Vertex_handle;

// Wall samples every kWallSpacing voxels. Between four samples h apart an empty sphere of radius r can
// bulge through the wall by about h^2 / (4 r): with h = 2 that is under 1/r voxel, so the spots of
// the balls that matter (r of a few voxels and more) stay where the exact walls would put them, and
// every value is capped by the exact wall distance anyway. The walls then cost 6 (N/2)^2 points,
// a few percent of the particles' boundary voxels.
constexpr int kWallSpacing = 2;
// Candidate values are kept in 1/16-voxel steps (rounded down, so they stay lower bounds): equal
// steps are ties, drawn in random order, and the buckets stay few.
constexpr double kSteps = 16;
// Vertices sit this far (at most, per axis) from their voxel centres, by a fixed pseudo-random
// offset: the voxel lattice is full of cospherical points, whose in-sphere tests CGAL must settle
// exactly; jittered, almost none are degenerate. Values are lowered by the offsets' length.
constexpr double kJitter = 0.005;
const double kJitterLength = kJitter * std::sqrt(3.0);
constexpr int kSampleModulus = 3;
// Hint cells for point location and nearest-vertex queries come from the latest vertex in the same
// block of this many voxels, so walks stay short.
constexpr int kHintBlock = 8;

Point pointOf(const Voxel& v) { return {double(v.x), double(v.y), double(v.z)}; }

// A fixed offset in [-kJitter, kJitter] per axis, a function of the voxel alone.
Point jitteredPointOf(const Voxel& v) {
  const std::uint64_t key = (std::uint64_t(std::uint32_t(v.x)) << 42) ^
                            (std::uint64_t(std::uint32_t(v.y)) << 21) ^ std::uint32_t(v.z);
  const auto offset = [key](std::uint64_t axis) {
    return kJitter * (double(deriveSeed(key, axis) >> 11) * 0x1.0p-53 * 2 - 1);
  };
  return {v.x + offset(0), v.y + offset(1), v.z + offset(2)};
}

// -1, -1+h, ..., n: the wall sample coordinates along one axis, ends included.
std::vector<int> wallSamples(int n) {
  std::vector<int> samples;
  for (int c = -1; c < n; c += kWallSpacing) samples.push_back(c);
  samples.push_back(n);
  return samples;
}

std::vector<Point> wallPoints(Dims dims) {
  const std::array<std::vector<int>, 3> samples{wallSamples(dims.x), wallSamples(dims.y),
                                                wallSamples(dims.z)};
  const std::array<int, 3> size{dims.x, dims.y, dims.z};
  std::vector<std::array<int, 3>> points;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    for (int layer : {-1, size[std::size_t(axis)]})
      for (int a : samples[std::size_t(u)])
        for (int b : samples[std::size_t(w)]) {
          std::array<int, 3> p{};
          p[std::size_t(axis)] = layer;
          p[std::size_t(u)] = a;
          p[std::size_t(w)] = b;
          points.push_back(p);
        }
  }
  std::sort(points.begin(), points.end());  // edges and corners are shared by two or three faces
  points.erase(std::unique(points.begin(), points.end()), points.end());
  std::vector<Point> out;
  out.reserve(points.size());
  for (const auto& p : points) out.emplace_back(p[0], p[1], p[2]);
  return out;
}

// Eight points farther than `reach` from every point of the volume [-1/2, n - 1/2]^3.
std::vector<Point> farCorners(Dims dims, double reach) {
  std::vector<Point> corners;
  const double far = 2 * reach + 1;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back((i & 1) ? dims.x + far : -far, (i & 2) ? dims.y + far : -far,
                         (i & 4) ? dims.z + far : -far);
  return corners;
}

class DelaunayField final : public SpaciousnessField {
public:
  DelaunayField(Dims dims, float maxRadius, bool periodic)
      : dims_(dims),
        periodic_(periodic),
        imageReach_(std::ceil(double(maxRadius)) + 1),
        maxRadius_(maxRadius),
        capKey_(std::uint32_t(std::floor(double(maxRadius) * kSteps))),
        buckets_(std::size_t(capKey_) + 1),
        occupied_(dims.count()),
        sampled_(dims.count()),
        spotSeen_(dims.count()),
        hintBlocks_{(dims.x + kHintBlock - 1) / kHintBlock, (dims.y + kHintBlock - 1) / kHintBlock,
                    (dims.z + kHintBlock - 1) / kHintBlock},
        hints_(hintBlocks_.count()) {
    const std::vector<Point> start = periodic ? farCorners(dims, imageReach_) : wallPoints(dims);
    triangulation_.insert(start.begin(), start.end());
    for (auto v = triangulation_.finite_vertices_begin(); v != triangulation_.finite_vertices_end(); ++v)
      rememberHint(v);
    for (auto c = triangulation_.finite_cells_begin(); c != triangulation_.finite_cells_end(); ++c)
      addCandidate(c);
  }

  PlacerKind kind() const override { return PlacerKind::Delaunay; }
  Dims dims() const override { return dims_; }
  bool periodic() const override { return periodic_; }
  float maxRadius() const override { return maxRadius_; }
  float slack() const override { return 1; }

  void insert(const std::vector<Voxel>& voxels) override {
    if (!periodic_) checkInside(dims_, voxels);
    for (const Voxel& v : voxels) occupied_.set(std::size_t(indexOf(v)));
    samplePoints(voxels);
    CGAL::spatial_sort(points_.begin(), points_.end(), Kernel());
    Cell hint = points_.empty() ? Cell() : hintCell(points_.front());
    pending_.clear();
    for (const Point& p : points_) {
      const Vertex v = insertPoint(p, hint);
      rememberHint(v);
      hint = v->cell();
    }
    addPendingCandidates();
  }

  // The nearest vertex's distance less its jitter bounds the distance to the sample; less the slack
  // too, the distance to the particles.
  float at(const Voxel& v) const override {
    checkInside(dims_, v);
    if (isOccupied(dims_.index(v))) return 0;
    const Point p = pointOf(v);
    const Vertex nearest = triangulation_.nearest_vertex(p, hintCell(p));
    const double sample = std::sqrt(CGAL::squared_distance(p, nearest->point())) - kJitterLength;
    const double bound =
        std::max(1.0, sample - double(slack()));  // a free voxel is a whole voxel from any other
    return float(std::min({bound, wallCap(v), double(maxRadius_)}));
  }

  std::vector<Voxel> bestFit(float radius, int maxCount, Rng& rng) override {
    std::vector<Voxel> spots;
    const double first = std::max(1.0, std::ceil(double(radius) * kSteps));
    for (std::size_t k = std::size_t(std::min(first, double(capKey_) + 1)); k <= capKey_; ++k) {
      std::vector<Entry>& bucket = buckets_[k];
      std::size_t taken = 0;
      while (int(spots.size()) < maxCount && taken < bucket.size()) {
        const std::size_t j = taken + std::size_t(uniformIndex(rng, bucket.size() - taken));
        const VoxelIndex spot = bucket[j].spot;
        if (isOccupied(spot)) {  // a particle covered the spot without destroying the cell
          dropCandidate(bucket[j].cell);
          continue;
        }
        swapEntries(bucket, taken++, j);
        if (!spotSeen_.testAndSet(spot))
          spots.push_back(dims_.voxel(spot));  // several cells may round to one spot
      }
      if (int(spots.size()) >= maxCount) break;
    }
    for (const Voxel& v : spots) spotSeen_.clearWordOf(dims_.index(v));  // all clear again
    return spots;
  }

  std::vector<Voxel> randomFit(float radius, int maxCount, Rng& rng) override {
    std::vector<Voxel> spots;
    const double first = std::max(1.0, std::ceil(double(radius) * kSteps));
    if (first > double(capKey_) || maxCount <= 0) return spots;
    sampleUniformly(buckets_, std::size_t(first), std::size_t(maxCount), rng, [&](const Entry& entry) {
      if (isOccupied(entry.spot)) return false;
      spots.push_back(dims_.voxel(entry.spot));
      return true;
    });
    return spots;
  }

  std::vector<std::pair<Voxel, float>> candidates() const override {
    std::vector<std::pair<Voxel, float>> out;
    for (std::uint32_t k = 1; k <= capKey_; ++k)
      for (const Entry& entry : buckets_[k])
        if (!isOccupied(entry.spot)) out.emplace_back(dims_.voxel(entry.spot), float(double(k) / kSteps));
    return out;
  }

private:
  struct Entry {
    Cell cell;
    VoxelIndex spot;
  };

  bool isOccupied(std::size_t i) const { return occupied_.test(i); }

  // The index of a voxel of the volume or, when it is periodic, of its image in it; -1 for a
  // voxel beyond a wall.
  std::ptrdiff_t indexOf(const Voxel& v) const {
    if (periodic_) return std::ptrdiff_t(dims_.index(dims_.wrap(v)));
    return dims_.contains(v.x, v.y, v.z) ? std::ptrdiff_t(dims_.index(v)) : -1;
  }

  // The walls' bound on a voxel's spaciousness; none in a periodic volume.
  double wallCap(const Voxel& v) const {
    return periodic_ ? double(maxRadius_) : double(wallDistance(dims_, v.x, v.y, v.z));
  }

  // A sample voxel's point, and in a periodic volume its images near the volume (see the top).
  void addPoints(const Voxel& v) {
    if (!periodic_) {
      points_.push_back(jitteredPointOf(v));
      return;
    }
    const Voxel w = dims_.wrap(v);
    const Point p = jitteredPointOf(w);
    for (const Voxel& s : periodicShifts(dims_, Box::at(w, {1, 1, 1}), int(imageReach_)))
      points_.emplace_back(p.x() + s.x, p.y() + s.y, p.z() + s.z);
  }

  // The new particle's boundary voxels that face free space, sampled (see the top of the file)
  // into points_, jittered.
  void samplePoints(const std::vector<Voxel>& voxels) {
    points_.clear();
    unsampled_.clear();
    const auto take = [&](const Voxel& v) {
      addPoints(v);
      sampled_.set(std::size_t(indexOf(v)));
    };
    for (const Voxel& v : boundaryVoxels(voxels))
      if (facesFreeSpace(v)) ((v.x + v.y + v.z) % kSampleModulus == 0 ? take(v) : unsampled_.push_back(v));
    const auto sampled = [&](int i, int j, int k) {
      const std::ptrdiff_t at = indexOf({i, j, k});
      return at >= 0 && sampled_.test(std::size_t(at));
    };
    for (const Voxel& v : unsampled_)
      if (!(sampled(v.x - 1, v.y, v.z) || sampled(v.x + 1, v.y, v.z) || sampled(v.x, v.y - 1, v.z) ||
            sampled(v.x, v.y + 1, v.z) || sampled(v.x, v.y, v.z - 1) || sampled(v.x, v.y, v.z + 1)))
        take(v);
  }

  // The nearest occupied voxel to any free voxel can be taken among those with a free 6-neighbour
  // (the argument of boundaryVoxels, applied to all particles together): a boundary voxel pressed
  // against other particles or a wall on every open side adds nothing but points to triangulate.
  bool facesFreeSpace(const Voxel& v) const {
    const auto free = [&](int i, int j, int k) {
      const std::ptrdiff_t at = indexOf({i, j, k});
      return at >= 0 && !isOccupied(std::size_t(at));
    };
    return free(v.x - 1, v.y, v.z) || free(v.x + 1, v.y, v.z) || free(v.x, v.y - 1, v.z) ||
           free(v.x, v.y + 1, v.z) || free(v.x, v.y, v.z - 1) || free(v.x, v.y, v.z + 1);
  }

  std::size_t hintIndex(const Point& p) const {
    const auto block = [](double c, int blocks) {
      return std::clamp(int(std::floor(c)) / kHintBlock, 0, blocks - 1);
    };
    return hintBlocks_.index(block(p.x(), hintBlocks_.x), block(p.y(), hintBlocks_.y),
                             block(p.z(), hintBlocks_.z));
  }

  void rememberHint(Vertex v) {
    hints_[hintIndex(v->point())] = v;
    latest_ = v;
  }

  Cell hintCell(const Point& p) const {
    const Vertex v = hints_[hintIndex(p)];
    return v != Vertex() ? v->cell() : latest_->cell();
  }

  // Bowyer-Watson by hand so that the destroyed cells are known: their candidates go. The new cells
  // (the star of the new vertex) are only noted: most die again while the rest of the particle's
  // boundary goes in, so their candidates are computed once the particle is complete.
  Vertex insertPoint(const Point& p, Cell hint) {
    Delaunay::Locate_type type;
    int li = 0, lj = 0;
    const Cell located = triangulation_.locate(p, type, li, lj, hint);
    if (type == Delaunay::VERTEX) return located->vertex(li);
    facets_.clear();
    conflicts_.clear();
    triangulation_.find_conflicts(p, located, std::back_inserter(facets_), std::back_inserter(conflicts_));
    for (Cell c : conflicts_) {
      dropCandidate(c);
      c->info().pending = false;
    }
    const Vertex v = triangulation_.insert_in_hole(p, conflicts_.begin(), conflicts_.end(),
                                                   facets_.front().first, facets_.front().second);
    const std::size_t before = pending_.size();
    triangulation_.incident_cells(v, std::back_inserter(pending_));
    for (std::size_t i = before; i < pending_.size(); ++i) pending_[i]->info().pending = true;
    return v;
  }

  // A noted cell may have died since (its slot then is free, or reused by a later new cell, noted
  // again: the pending flag makes each count once).
  void addPendingCandidates() {
    const auto& cells = triangulation_.tds().cells();
    for (Cell c : pending_) {
      if (!cells.is_used(c) || !c->info().pending) continue;
      c->info().pending = false;
      if (!triangulation_.is_infinite(c)) addCandidate(c);
    }
  }

  // The ball around the rounded circumcentre that fits in the circumsphere, less the jitter, holds
  // no sampled voxel, and shrunk by the slack no boundary voxel, hence (see boundaryVoxels) no
  // occupied voxel, as long as the spot itself is empty. The paper subtracts 1 for the rounding;
  // the offset itself (at most sqrt(3)/2) is the exact amount.
  void addCandidate(Cell c) {
    const Point centre = CGAL::circumcenter(c->vertex(0)->point(), c->vertex(1)->point(),
                                            c->vertex(2)->point(), c->vertex(3)->point());
    const auto inside = [](double x, int n) { return x >= -0.5 && x < n - 0.5; };
    if (!inside(centre.x(), dims_.x) || !inside(centre.y(), dims_.y) || !inside(centre.z(), dims_.z)) return;
    const auto round = [](double x) {
      return int(std::floor(x + 0.5));
    };  // lround(-0.5) would leave the volume
    const Voxel spot{round(centre.x()), round(centre.y()), round(centre.z())};
    const std::size_t index = dims_.index(spot);
    if (isOccupied(index)) return;
    const double radius = std::sqrt(CGAL::squared_distance(centre, c->vertex(0)->point()));
    const double offset = std::sqrt(CGAL::squared_distance(centre, pointOf(spot)));
    const double value = std::min({radius - offset - kJitterLength, wallCap(spot), double(maxRadius_)});
    const double key = std::floor(value * kSteps);
    if (key < 1) return;
    std::vector<Entry>& bucket = buckets_[std::size_t(key)];
    c->info() = {std::uint32_t(key), std::uint32_t(bucket.size()), false};
    bucket.push_back({c, VoxelIndex(index)});
  }

  void dropCandidate(Cell c) {
    const QueueSlot slot = c->info();
    if (slot.bucket == 0) return;
    std::vector<Entry>& bucket = buckets_[slot.bucket];
    bucket[slot.pos] = bucket.back();
    bucket[slot.pos].cell->info().pos = slot.pos;
    bucket.pop_back();
    c->info().bucket = 0;
  }

  static void swapEntries(std::vector<Entry>& bucket, std::size_t a, std::size_t b) {
    std::swap(bucket[a], bucket[b]);
    bucket[a].cell->info().pos = std::uint32_t(a);
    bucket[b].cell->info().pos = std::uint32_t(b);
  }

  Dims dims_;
  bool periodic_;
  double imageReach_;  ///< images of sample points are kept this far around a periodic volume
  float maxRadius_;
  std::uint32_t capKey_;
  Delaunay triangulation_;
  std::vector<std::vector<Entry>> buckets_;  ///< bucket k: candidates of value k / kSteps
  VoxelBits occupied_;
  VoxelBits sampled_;   ///< triangulation vertices
  VoxelBits spotSeen_;  ///< spots bestFit has taken (empty between calls)
  Dims hintBlocks_;
  std::vector<Vertex> hints_;
  Vertex latest_;
  std::vector<Delaunay::Facet> facets_;
  std::vector<Cell> conflicts_, pending_;
  std::vector<Point> points_;
  std::vector<Voxel> unsampled_;
};

}  // namespace

std::unique_ptr<SpaciousnessField> makeDelaunayField(Dims dims, float maxRadius, bool periodic) {
  return std::make_unique<DelaunayField>(dims, maxRadius, periodic);
}

}  // namespace solidtex::placement::detail
