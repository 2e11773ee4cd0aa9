// Exact Euclidean spaciousness, updated locally after each insertion. Values only ever drop, so a
// voxel's new value is min(old, exact squared distance to the new particle), computed by a separable
// EDT (Felzenszwalb & Huttenlocher) where it can matter. Blocks of 8^3 voxels remember an upper
// bound of their values; a block whose distance to the particle is already at least that bound
// cannot change and is skipped. The first two EDT passes only touch the particle's z-slab (other
// planes hold no particle voxel); the last pass is evaluated in the affected blocks only and fused
// with the comparison against the old values.
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "common/squaredDistanceTransform.h"
#include "placement/detail/BucketField.h"

namespace solidtex::placement::detail {
namespace {

constexpr int kBlock = 8;
double squared(double v) { return v * v; }

// Squared gap between the voxels of the half-open intervals [a0,a1) and [b0,b1).
double squaredGap(int a0, int a1, int b0, int b1) { return squared(std::max({0, b0 - a1 + 1, a0 - b1 + 1})); }

// Where the particle is: its box, and a ball around the box centre holding all its voxels.
struct ParticleBounds {
  Box box;
  double cx, cy, cz, radius;
};

ParticleBounds boundsOf(const std::vector<Voxel>& voxels) {
  const Box box = boundingBox(voxels);
  ParticleBounds b{box, (box.lo.x + box.hi.x - 1) / 2.0, (box.lo.y + box.hi.y - 1) / 2.0,
                   (box.lo.z + box.hi.z - 1) / 2.0, 0};
  for (const Voxel& v : voxels)
    b.radius = std::max(b.radius, squared(v.x - b.cx) + squared(v.y - b.cy) + squared(v.z - b.cz));
  b.radius = std::sqrt(b.radius);
  return b;
}

// A lower bound of the squared distance from any voxel of `block` to any voxel of the particle: the
// larger of the gap between the boxes and the gap between the block and the particle's ball.
double squaredGapBound(const Box& block, const ParticleBounds& p) {
  const double boxGap = squaredGap(block.lo.x, block.hi.x, p.box.lo.x, p.box.hi.x) +
                        squaredGap(block.lo.y, block.hi.y, p.box.lo.y, p.box.hi.y) +
                        squaredGap(block.lo.z, block.hi.z, p.box.lo.z, p.box.hi.z);
  const auto axis = [](double c, int lo, int hi) {
    const int last = hi - 1;
    return c < lo ? lo - c : c > last ? c - last : 0.0;
  };
  const double toBlock =
      std::sqrt(squared(axis(p.cx, block.lo.x, block.hi.x)) + squared(axis(p.cy, block.lo.y, block.hi.y)) +
                squared(axis(p.cz, block.lo.z, block.hi.z)));
  const double ballGap = std::max(0.0, toBlock - p.radius - 1e-6);  // margin: a safe bound despite rounding
  return std::max(boxGap, ballGap * ballGap);
}

template <class Key>
class EdtField final : public BucketField<Key> {
public:
  EdtField(Dims dims, float maxRadius, bool periodic)
      : BucketField<Key>(dims, periodic, squaredDistanceValues(maxRadius),
                         [](int wall) { return std::uint64_t(wall) * std::uint64_t(wall); }),
        blocks_{(dims.x + kBlock - 1) / kBlock, (dims.y + kBlock - 1) / kBlock,
                (dims.z + kBlock - 1) / kBlock},
        blockMax_(blocks_.count()) {
    tbb::parallel_for(std::size_t(0), blocks_.count(), [&](std::size_t b) { blockMax_[b] = scanBlock(b); });
  }

  PlacerKind kind() const override { return PlacerKind::Edt; }

  void insert(const std::vector<Voxel>& voxels) override {
    this->occupy(voxels);
    if (voxels.empty()) return;
    for (const Voxel& shift : this->imageShifts(voxels)) {
      if (shift == Voxel{})
        lowerTowards(voxels);
      else
        lowerTowards(shifted(voxels, shift));
    }
  }

private:
  // Lowers the voxels near the particle's voxels (some may lie outside the volume: images of a
  // periodic volume's particle) to their distance from them.
  void lowerTowards(const std::vector<Voxel>& voxels) {
    const ParticleBounds particle = boundsOf(voxels);
    findAffectedBlocks(particle);
    if (affected_.empty()) return;
    transformSlab(voxels, particle.box);
    evaluateColumns(particle.box);
    for (std::size_t i = 0; i < affected_.size(); ++i)
      for (const auto& [v, key] : changes_[i]) this->queue_.lower(v, key);
  }

  // The affected blocks of one column of blocks (same bx, by) are affected_[first, first + count).
  struct BlockColumn {
    int bx, by;
    std::size_t first, count;
  };

  Box blockBox(int bx, int by, int bz) const {
    const Dims& d = this->dims_;
    return {{bx * kBlock, by * kBlock, bz * kBlock},
            {std::min(bx * kBlock + kBlock, d.x), std::min(by * kBlock + kBlock, d.y),
             std::min(bz * kBlock + kBlock, d.z)}};
  }

  Key scanBlock(std::size_t b) const {
    const Voxel c = blocks_.voxel(b);
    const Box box = blockBox(c.x, c.y, c.z);
    Key most = 0;
    for (int z = box.lo.z; z < box.hi.z; ++z)
      for (int y = box.lo.y; y < box.hi.y; ++y)
        for (int x = box.lo.x; x < box.hi.x; ++x)
          most = std::max(most, this->queue_.key(VoxelIndex(this->dims_.index(x, y, z))));
    return most;
  }

  // Fills affected_ (grouped by block column) with the blocks whose values may drop, and sub_ with
  // the x-y extent of their union and the particle.
  void findAffectedBlocks(const ParticleBounds& particle) {
    affected_.clear();
    columns_.clear();
    const Box& p = particle.box;
    const Dims& d = this->dims_;
    const int reach = int(std::ceil(std::sqrt(double(this->capKey()))));
    const Voxel lo{std::max(p.lo.x - reach, 0) / kBlock, std::max(p.lo.y - reach, 0) / kBlock,
                   std::max(p.lo.z - reach, 0) / kBlock};
    const Voxel hi{std::min(p.hi.x - 1 + reach, d.x - 1) / kBlock,
                   std::min(p.hi.y - 1 + reach, d.y - 1) / kBlock,
                   std::min(p.hi.z - 1 + reach, d.z - 1) / kBlock};
    sub_ = p;
    for (int by = lo.y; by <= hi.y; ++by)
      for (int bx = lo.x; bx <= hi.x; ++bx) {
        const std::size_t first = affected_.size();
        for (int bz = lo.z; bz <= hi.z; ++bz) {
          const std::size_t b = blocks_.index(bx, by, bz);
          if (squaredGapBound(blockBox(bx, by, bz), particle) >= double(blockMax_[b])) continue;
          affected_.push_back(b);
        }
        if (affected_.size() == first) continue;
        columns_.push_back({bx, by, first, affected_.size() - first});
        const Box box = blockBox(bx, by, 0);
        sub_.lo = {std::min(sub_.lo.x, box.lo.x), std::min(sub_.lo.y, box.lo.y), p.lo.z};
        sub_.hi = {std::max(sub_.hi.x, box.hi.x), std::max(sub_.hi.y, box.hi.y), p.hi.z};
      }
    if (changes_.size() < affected_.size()) changes_.resize(affected_.size());
  }

  // slab_ over sub_'s x-y extent and the particle's z range: squared distance to the particle's
  // voxels within each z plane (the EDT's passes along x and y).
  void transformSlab(const std::vector<Voxel>& voxels, const Box& p) {
    slabDims_ = {sub_.hi.x - sub_.lo.x, sub_.hi.y - sub_.lo.y, p.hi.z - p.lo.z};
    slab_.assign(slabDims_.count(), kNoSite);
    for (const Voxel& v : voxels) slab_[slabDims_.index(v.x - sub_.lo.x, v.y - sub_.lo.y, v.z - p.lo.z)] = 0;
    const int sx = slabDims_.x, sy = slabDims_.y, py = p.hi.y - p.lo.y, y0 = p.lo.y - sub_.lo.y;
    const std::ptrdiff_t plane = std::ptrdiff_t(sx) * sy;
    // Along x, only rows that hold particle voxels; along y, every line of the slab.
    transformLines(py * slabDims_.z, sx, 1,
                   [&](int line) { return (line / py) * plane + (y0 + line % py) * sx; });
    transformLines(sx * slabDims_.z, sy, sx, [&](int line) { return (line / sx) * plane + line % sx; });
  }

  template <class LineStart>
  void transformLines(int lines, int length, std::ptrdiff_t stride, LineStart start) {
    tbb::parallel_for(tbb::blocked_range<int>(0, lines, 64), [&](const tbb::blocked_range<int>& range) {
      LowerEnvelope envelope(length);
      for (int line = range.begin(); line != range.end(); ++line)
        transformLine(slab_.data() + start(line), length, stride, envelope);
    });
  }

  // The EDT's pass along z, evaluated only inside affected blocks, fused with the comparison against
  // the old values: changes_[i] gets block affected_[i]'s drops in index order and its bound is
  // renewed. Columns run in parallel; the changes are applied afterwards in block order, so the
  // result does not depend on the thread count.
  void evaluateColumns(const Box& p) {
    const std::ptrdiff_t plane = std::ptrdiff_t(slabDims_.x) * slabDims_.y;
    tbb::parallel_for(std::size_t(0), columns_.size(), [&](std::size_t c) {
      const BlockColumn& column = columns_[c];
      for (std::size_t i = column.first; i < column.first + column.count; ++i) changes_[i].clear();
      std::vector<Key> most(column.count);  // the new bound of each affected block of the column
      LowerEnvelope envelope(slabDims_.z);
      const Box cells = blockBox(column.bx, column.by, 0);
      for (int y = cells.lo.y; y < cells.hi.y; ++y)
        for (int x = cells.lo.x; x < cells.hi.x; ++x) {
          envelope.build(slab_.data() + (y - sub_.lo.y) * slabDims_.x + (x - sub_.lo.x), slabDims_.z, plane,
                         p.lo.z);
          for (std::size_t i = column.first; i < column.first + column.count; ++i)
            most[i - column.first] =
                std::max(most[i - column.first], lowerLine(x, y, affected_[i], envelope, changes_[i]));
        }
      for (std::size_t i = column.first; i < column.first + column.count; ++i)
        blockMax_[affected_[i]] = most[i - column.first];
    });
  }

  // One voxel line of one block: records the drops and returns the line's largest new key.
  Key lowerLine(int x, int y, std::size_t block, LowerEnvelope& envelope,
                std::vector<std::pair<VoxelIndex, Key>>& changes) const {
    const int bz = int(block / (std::size_t(blocks_.x) * std::size_t(blocks_.y)));
    const int z0 = bz * kBlock, z1 = std::min(z0 + kBlock, this->dims_.z);
    Key most = 0;
    for (int z = z0; z < z1; ++z) {
      const auto v = VoxelIndex(this->dims_.index(x, y, z));
      const Key old = this->queue_.key(v);
      const std::uint32_t d = envelope.at(z);
      if (d < old) changes.emplace_back(v, Key(d));
      most = std::max(most, d < old ? Key(d) : old);
    }
    return most;
  }

  Dims blocks_;
  std::vector<Key> blockMax_;  ///< upper bound of the keys in each block
  std::vector<std::size_t> affected_;
  std::vector<BlockColumn> columns_;
  std::vector<std::vector<std::pair<VoxelIndex, Key>>> changes_;
  Box sub_;
  Dims slabDims_;
  std::vector<std::uint32_t> slab_;
};

}  // namespace

std::unique_ptr<SpaciousnessField> makeEdtField(Dims dims, float maxRadius, bool periodic) {
  return makeWithNarrowestKey<EdtField>(squaredDistanceValues(maxRadius).size() - 1, dims, maxRadius,
                                        periodic);
}

}  // namespace solidtex::placement::detail
