#include "validation/volumeQuality.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_set>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <Eigen/Dense>

#include "common/Error.h"
#include "common/Random.h"
#include "common/distributionDistance.h"
#include "common/secondsSince.h"

// How the nearest patch is found, and how far to trust it.
//
// A 5^3 RGB patch has 375 components and a 64^3 volume holds 216,000 of them: brute force would cost
// about 1e12 operations per measure. Instead every patch x is mapped to a search point: its
// coordinates c = U^T (x - mean) on the leading principal components U (orthonormal, from a sample of
// the exemplar's patches) and the norm r of the rest, |x - mean - U c|. For two patches, by Pythagoras
// and the triangle inequality in the orthogonal complement of U,
//     |c_q - c_t|^2 + (r_q - r_t)^2  <=  |q - t|^2:
// the search-space distance is a lower bound of the true one. A kd-tree over the search points of
// every target patch is searched by branch and bound, best bin first: every target reached below the
// current bound is compared in full, and the bound shrinks to the best full distance found. When the
// boxes of all unvisited nodes lie beyond the bound, no target left can be nearer: the answer is
// exact. Where the bound is loose (patches with much of their variance outside the components: noise,
// the shuffled copy), a search stops after visiting searchBudget targets and reports the best so far:
// the distance to a real patch, so never an underestimate; VolumeQuality::exactShare says how often
// that happened. Against brute force (the tests; 64^3 volumes, 1 and 3 channels, default options)
// the means come out at most about 1 % high for textured volumes, 3 % for smooth RGB volumes whose
// channels are independent, and 2-4 % high for noise and shuffled copies, which leaves the ratio to
// the shuffled level a few percent optimistic at worst. (nanoflann's depth-first search cannot stop
// early with a good answer and took tens of seconds on noise-like patches, hence the own tree.)
// Rounding (float coordinates, r from a difference of squares) is covered by a slack on the bound.

namespace solidtex {
namespace {

// Every patch of sx x sy x sz voxels lying wholly inside one of several frames of equal size (a
// volume, or the slices of one, each a volume one voxel thick), as a vector x fastest, channel
// innermost.
class PatchSet {
public:
  PatchSet(std::vector<const DenseVolume*> frames, int sx, int sy, int sz)
      : frames_(std::move(frames)), size_{sx, sy, sz} {
    const Dims& d = frames_.front()->dims;
    span_ = {d.x - sx + 1, d.y - sy + 1, d.z - sz + 1};
    perFrame_ = std::int64_t(span_[0]) * span_[1] * span_[2];
  }
  std::int64_t size() const { return perFrame_ * std::int64_t(frames_.size()); }
  int dims() const { return size_[0] * size_[1] * size_[2] * channels(); }
  int channels() const { return frames_.front()->channels; }

  void extract(std::int64_t index, float* out) const {
    const DenseVolume& frame = *frames_[std::size_t(index / perFrame_)];
    index %= perFrame_;
    const int i = int(index % span_[0]), j = int(index / span_[0] % span_[1]),
              k = int(index / (std::int64_t(span_[0]) * span_[1]));
    const int row = size_[0] * channels();
    for (int dz = 0; dz < size_[2]; ++dz)
      for (int dy = 0; dy < size_[1]; ++dy, out += row) std::copy_n(frame.at(i, j + dy, k + dz), row, out);
  }

  // Squared distance between the patch `index` and `patch` (dims() floats), summed row by row; stops
  // early, with a partial sum >= limit, once it reaches `limit`.
  double squaredDistance(std::int64_t index, const float* patch, double limit) const {
    const DenseVolume& frame = *frames_[std::size_t(index / perFrame_)];
    index %= perFrame_;
    const int i = int(index % span_[0]), j = int(index / span_[0] % span_[1]),
              k = int(index / (std::int64_t(span_[0]) * span_[1]));
    const int row = size_[0] * channels();
    double sum = 0;
    for (int dz = 0; dz < size_[2]; ++dz)
      for (int dy = 0; dy < size_[1]; ++dy, patch += row) {
        const float* target = frame.at(i, j + dy, k + dz);
        float rowSum = 0;
        for (int c = 0; c < row; ++c) rowSum += (patch[c] - target[c]) * (patch[c] - target[c]);
        sum += rowSum;
        if (sum >= limit) return sum;
      }
    return sum;
  }

private:
  std::vector<const DenseVolume*> frames_;
  std::array<int, 3> size_, span_;
  std::int64_t perFrame_ = 0;
};

// Whether a patch of this size fits in frames of these dims.
bool fits(const Dims& d, int sx, int sy, int sz) { return d.x >= sx && d.y >= sy && d.z >= sz; }

// `count` distinct indices in [0, n), ascending (Floyd's algorithm); all of them when count >= n.
std::vector<std::int64_t> sampleIndices(std::int64_t n, int count, std::uint64_t seed) {
  std::vector<std::int64_t> out;
  if (count >= n) {
    out.resize(std::size_t(n));
    std::iota(out.begin(), out.end(), std::int64_t(0));
    return out;
  }
  Rng rng(seed);
  std::unordered_set<std::int64_t> chosen;
  for (std::int64_t j = n - count; j < n; ++j) {
    const auto t = std::int64_t(uniformIndex(rng, std::uint64_t(j + 1)));
    chosen.insert(chosen.count(t) ? j : t);
  }
  out.assign(chosen.begin(), chosen.end());
  std::sort(out.begin(), out.end());
  return out;
}

// The leading principal components of a sample of the patches.
struct Basis {
  Eigen::VectorXf mean;
  Eigen::MatrixXf transposed;  // components x dims, orthonormal rows
};

Basis fitBasis(const PatchSet& set, int components, std::uint64_t seed) {
  const std::vector<std::int64_t> sample = sampleIndices(set.size(), 4096, seed);
  const int dims = set.dims(), n = int(sample.size());
  Eigen::MatrixXf x(dims, n);
  for (int s = 0; s < n; ++s) set.extract(sample[std::size_t(s)], x.col(s).data());
  Basis b;
  b.mean = x.cast<double>().rowwise().mean().cast<float>();
  x.colwise() -= b.mean;
  const Eigen::MatrixXd covariance = (x * x.transpose()).cast<double>() / double(n);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(covariance);  // ascending eigenvalues
  const int m = std::min(components, dims);
  b.transposed = eigen.eigenvectors().rightCols(m).rowwise().reverse().transpose().cast<float>();
  return b;
}

// Search points (components then the residual norm) of the patches `indices` of the set, row-major.
std::vector<float> project(const PatchSet& set, const Basis& basis,
                           const std::vector<std::int64_t>& indices) {
  const int dims = set.dims(), m = int(basis.transposed.rows()), stride = m + 1;
  std::vector<float> points(indices.size() * std::size_t(stride));
  constexpr std::size_t chunk = 1024;  // fixed, so that results do not depend on the scheduling
  const std::size_t chunks = (indices.size() + chunk - 1) / chunk;
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
    const std::size_t begin = c * chunk, n = std::min(indices.size(), begin + chunk) - begin;
    Eigen::MatrixXf x(dims, Eigen::Index(n));
    for (std::size_t s = 0; s < n; ++s) set.extract(indices[begin + s], x.col(Eigen::Index(s)).data());
    x.colwise() -= basis.mean;
    const Eigen::MatrixXf coords = basis.transposed * x;
    // In double: the difference of squares cancels where the components hold almost all of a patch.
    const Eigen::RowVectorXd norms = x.cast<double>().colwise().squaredNorm(),
                             inBasis = coords.cast<double>().colwise().squaredNorm();
    for (std::size_t s = 0; s < n; ++s) {
      const auto col = Eigen::Index(s);
      float* p = &points[(begin + s) * std::size_t(stride)];
      std::copy_n(coords.col(col).data(), m, p);
      p[m] = float(std::sqrt(std::max(0.0, norms(col) - inBasis(col))));
    }
  });
  return points;
}

std::vector<std::int64_t> allIndices(std::int64_t n) {
  std::vector<std::int64_t> all(static_cast<std::size_t>(n));
  std::iota(all.begin(), all.end(), std::int64_t(0));
  return all;
}

struct Nearest {
  double squaredDistance = std::numeric_limits<double>::infinity();
  bool exact = true;
};

// Per-thread buffers of the searches.
struct SearchScratch {
  std::vector<float> patch;
  std::vector<std::pair<float, std::uint32_t>> heap;  // (lower bound, node)
};

// Every patch of a set as a search point, in a kd-tree: a complete binary tree split at the median of
// the widest coordinate, each node with the bounding box of its points, leaves of about 32 points.
// Its shape depends only on the points, never on the scheduling.
class SearchIndex {
public:
  SearchIndex(const PatchSet& set, const Basis& basis, float slack, int budget)
      : set_(set), stride_(int(basis.transposed.rows()) + 1), slack_(slack), budget_(budget) {
    points_ = project(set, basis, allIndices(set.size()));
    const std::size_t n = std::size_t(set.size());
    while ((n >> depth_) > 32) ++depth_;  // leaves of 16 to 32 points
    const std::size_t nodes = (std::size_t(2) << depth_) - 1;
    lo_.resize(nodes * std::size_t(stride_));
    hi_.resize(nodes * std::size_t(stride_));
    begin_.resize(nodes);
    end_.resize(nodes);
    ids_.resize(n);
    std::iota(ids_.begin(), ids_.end(), std::uint32_t(0));
    build(0, 0, n, 0);
  }

  // The target nearest to the query (its full patch and its search point), by branch and bound: down
  // to the nearer leaf, the other children waiting in a heap by the lower bound of their boxes (best
  // bin first); each target below the bound is compared in full and the bound follows the best full
  // distance. Exact when the bound stops it, an upper bound when the budget does.
  Nearest nearest(const float* patch, const float* point, SearchScratch& s) const {
    Nearest best;
    float bound = std::numeric_limits<float>::infinity();
    const auto later = [](const std::pair<float, std::uint32_t>& a,
                          const std::pair<float, std::uint32_t>& b) {
      return a.first > b.first || (a.first == b.first && a.second > b.second);
    };
    s.heap.clear();
    s.heap.emplace_back(boxBound(0, point), 0u);
    int visited = 0;
    while (!s.heap.empty()) {
      std::pop_heap(s.heap.begin(), s.heap.end(), later);
      auto [lower, node] = s.heap.back();
      s.heap.pop_back();
      if (lower >= bound) return best;  // every node left is at least as far
      if (visited >= budget_) {
        best.exact = false;
        return best;
      }
      while (!isLeaf(node) && lower < bound) {
        const std::uint32_t a = 2 * node + 1, b = a + 1;
        const float la = boxBound(a, point), lb = boxBound(b, point);
        const bool aFirst = la <= lb;
        const float farther = aFirst ? lb : la;
        if (farther < bound) {
          s.heap.emplace_back(farther, aFirst ? b : a);
          std::push_heap(s.heap.begin(), s.heap.end(), later);
        }
        node = aFirst ? a : b;
        lower = aFirst ? la : lb;
      }
      if (lower >= bound) continue;
      for (std::uint32_t slot = begin_[node]; slot < end_[node]; ++slot) {
        if (squared(point, &points_[std::size_t(slot) * std::size_t(stride_)]) >= bound) continue;
        const double d2 = set_.squaredDistance(ids_[slot], patch, best.squaredDistance);
        if (d2 < best.squaredDistance) {
          best.squaredDistance = d2;
          const double b = std::sqrt(d2) + slack_;
          bound = float(b * b);
        }
      }
      visited += int(end_[node] - begin_[node]);
    }
    return best;
  }

private:
  bool isLeaf(std::uint32_t node) const { return node >= (std::uint32_t(1) << depth_) - 1; }

  float squared(const float* a, const float* b) const {
    float sum = 0;
    for (int d = 0; d < stride_; ++d) sum += (a[d] - b[d]) * (a[d] - b[d]);
    return sum;
  }

  float boxBound(std::uint32_t node, const float* point) const {
    const float *lo = &lo_[std::size_t(node) * std::size_t(stride_)],
                *hi = &hi_[std::size_t(node) * std::size_t(stride_)];
    float sum = 0;
    for (int d = 0; d < stride_; ++d) {
      const float gap = std::max({lo[d] - point[d], point[d] - hi[d], 0.0f});
      sum += gap * gap;
    }
    return sum;
  }

  float* row(std::size_t slot) { return &points_[slot * std::size_t(stride_)]; }

  // Reorders the points of node `node` (slots [begin, end)) so that its first half holds the smaller
  // half by the widest coordinate (ties by id), and builds the children.
  void build(std::uint32_t node, std::size_t begin, std::size_t end, int level) {
    begin_[node] = std::uint32_t(begin);
    end_[node] = std::uint32_t(end);
    float *lo = &lo_[std::size_t(node) * std::size_t(stride_)],
          *hi = &hi_[std::size_t(node) * std::size_t(stride_)];
    std::fill_n(lo, stride_, std::numeric_limits<float>::infinity());
    std::fill_n(hi, stride_, -std::numeric_limits<float>::infinity());
    for (std::size_t s = begin; s < end; ++s) {
      const float* p = row(s);
      for (int d = 0; d < stride_; ++d) {
        lo[d] = std::min(lo[d], p[d]);
        hi[d] = std::max(hi[d], p[d]);
      }
    }
    if (level == depth_) return;
    int widest = 0;
    for (int d = 1; d < stride_; ++d)
      if (hi[d] - lo[d] > hi[widest] - lo[widest]) widest = d;
    const std::size_t mid = begin + (end - begin) / 2;
    select(begin, end, mid, widest);
    auto left = [&] { build(2 * node + 1, begin, mid, level + 1); };
    auto right = [&] { build(2 * node + 2, mid, end, level + 1); };
    if (end - begin > 4096)
      tbb::parallel_invoke(left, right);
    else {
      left();
      right();
    }
  }

  // Quickselect on whole rows: puts the k-th smallest of [begin, end) by (coordinate `dim`, id) at k,
  // the smaller ones before it. Ids are distinct, so the order is total and the result unique.
  void select(std::size_t begin, std::size_t end, std::size_t k, int dim) {
    const auto less = [&](std::size_t a, std::size_t b) {
      const float pa = row(a)[dim], pb = row(b)[dim];
      return pa < pb || (pa == pb && ids_[a] < ids_[b]);
    };
    const auto swap = [&](std::size_t a, std::size_t b) {
      std::swap_ranges(row(a), row(a) + stride_, row(b));
      std::swap(ids_[a], ids_[b]);
    };
    while (end - begin > 1) {
      const std::size_t last = end - 1, m = begin + (end - begin) / 2;  // median of three to `last`
      if (less(m, begin)) swap(m, begin);
      if (less(last, begin)) swap(last, begin);
      if (less(m, last)) swap(m, last);
      std::size_t store = begin;
      for (std::size_t i = begin; i < last; ++i)
        if (less(i, last)) swap(i, store++);
      swap(store, last);
      if (store == k) return;
      if (k < store)
        end = store;
      else
        begin = store + 1;
    }
  }

  const PatchSet& set_;
  int stride_;
  float slack_;
  int budget_;
  int depth_ = 0;
  std::vector<float> points_, lo_, hi_;  // points in tree order; boxes per node
  std::vector<std::uint32_t> ids_, begin_, end_;
};

struct Similarity {
  double coherence = 0, completeness = 0;
  std::int64_t searches = 0, exact = 0;
};

// Mean RMS distance from the patches `queries` of `from` (their search points already projected) to
// their nearest patch in `to`.
double meanNearest(const PatchSet& from, const std::vector<std::int64_t>& queries,
                   const std::vector<float>& points, const SearchIndex& to, Similarity& counts) {
  const int dims = from.dims();
  const std::size_t stride = points.size() / std::max<std::size_t>(queries.size(), 1);
  std::vector<Nearest> found(queries.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, queries.size(), 16),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      SearchScratch s;
                      s.patch.resize(std::size_t(dims));
                      for (std::size_t q = r.begin(); q < r.end(); ++q) {
                        from.extract(queries[q], s.patch.data());
                        found[q] = to.nearest(s.patch.data(), &points[q * stride], s);
                      }
                    });
  double sum = 0;  // in query order: the same for any thread count
  for (const Nearest& n : found) {
    sum += std::sqrt(n.squaredDistance / dims);
    counts.exact += n.exact;
  }
  counts.searches += std::int64_t(found.size());
  return found.empty() ? 0.0 : sum / double(found.size());
}

// Coherence and completeness of each of `outputs` against `exemplar`, with the same samples for all.
std::vector<Similarity> compare(const PatchSet& exemplar, const std::vector<PatchSet>& outputs,
                                const VolumeQualityOptions& o, float slackPerComponent, std::uint64_t seed) {
  const Basis basis = fitBasis(exemplar, o.searchDims, deriveSeed(seed, 0));
  const float slack = slackPerComponent * std::sqrt(float(exemplar.dims()));
  const SearchIndex exemplarIndex(exemplar, basis, slack, o.searchBudget);
  const std::vector<std::int64_t> exemplarQueries =
      sampleIndices(exemplar.size(), o.samples, deriveSeed(seed, 1));
  const std::vector<float> exemplarPoints = project(exemplar, basis, exemplarQueries);
  const std::vector<std::int64_t> outputQueries =
      sampleIndices(outputs.front().size(), o.samples, deriveSeed(seed, 2));
  std::vector<Similarity> out(outputs.size());
  for (std::size_t s = 0; s < outputs.size(); ++s) {
    const SearchIndex outputIndex(outputs[s], basis, slack, o.searchBudget);
    const std::vector<float> outputPoints = project(outputs[s], basis, outputQueries);
    out[s].coherence = meanNearest(outputs[s], outputQueries, outputPoints, exemplarIndex, out[s]);
    out[s].completeness = meanNearest(exemplar, exemplarQueries, exemplarPoints, outputIndex, out[s]);
  }
  return out;
}

// The slice of `v` normal to `axis` at `offset`, as a volume one voxel thick: normal to x it spans
// (y, z), normal to y (x, z), normal to z (x, y).
DenseVolume sliceOf(const DenseVolume& v, int axis, int offset) {
  DenseVolume s;
  const Dims& d = v.dims;
  s.dims = axis == 0 ? Dims{d.y, d.z, 1} : axis == 1 ? Dims{d.x, d.z, 1} : Dims{d.x, d.y, 1};
  s.channels = v.channels;
  s.values.resize(s.dims.count() * std::size_t(v.channels));
  for (int b = 0; b < s.dims.y; ++b)
    for (int a = 0; a < s.dims.x; ++a) {
      const float* src = axis == 0 ? v.at(offset, a, b) : axis == 1 ? v.at(a, offset, b) : v.at(a, b, offset);
      std::copy_n(src, v.channels, s.at(a, b, 0));
    }
  return s;
}

// `count` evenly spaced slices of `v` normal to `axis` (all of them when it has fewer).
std::vector<DenseVolume> slicesOf(const DenseVolume& v, int axis, int count) {
  const int n = axis == 0 ? v.dims.x : axis == 1 ? v.dims.y : v.dims.z;
  std::vector<int> offsets;
  for (int s = 0; s < count; ++s) offsets.push_back(int((s + 0.5) * n / count));
  offsets.erase(std::unique(offsets.begin(), offsets.end()), offsets.end());
  std::vector<DenseVolume> slices;
  for (int offset : offsets) slices.push_back(sliceOf(v, axis, offset));
  return slices;
}

std::vector<const DenseVolume*> pointers(const std::vector<DenseVolume>& volumes) {
  std::vector<const DenseVolume*> p;
  for (const DenseVolume& v : volumes) p.push_back(&v);
  return p;
}

void checkVolume(const DenseVolume& v, const char* name) {
  if (v.channels <= 0 || v.dims.x <= 0 || v.dims.y <= 0 || v.dims.z <= 0 ||
      v.values.size() != v.dims.count() * std::size_t(v.channels))
    throw InputError(std::string("the ") + name + " volume's values do not match its size");
  if (!std::all_of(v.values.begin(), v.values.end(), [](float x) { return std::isfinite(x); }))
    throw InputError(std::string("the ") + name + " volume holds values that are not finite");
}

DenseVolume shuffled(const DenseVolume& v, std::uint64_t seed) {
  DenseVolume s = v;
  Rng rng(seed);
  const std::size_t c = std::size_t(v.channels);
  for (std::size_t i = v.dims.count(); i > 1; --i) {
    const std::size_t j = std::size_t(uniformIndex(rng, i));
    std::swap_ranges(&s.values[(i - 1) * c], &s.values[i * c], &s.values[j * c]);
  }
  return s;
}

std::vector<double> valueWasserstein(const DenseVolume& a, const DenseVolume& b) {
  std::vector<double> w(std::size_t(a.channels), 0.0);
  tbb::parallel_for(0, a.channels, [&](int c) {
    auto channel = [c](const DenseVolume& v) {
      std::vector<double> values(v.dims.count());
      for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = v.values[i * std::size_t(v.channels) + std::size_t(c)];
      return values;
    };
    w[std::size_t(c)] = wasserstein1(channel(a), channel(b));
  });
  return w;
}

}  // namespace

VolumeQuality measureVolumeQuality(const DenseVolume& output, const DenseVolume& exemplar,
                                   const VolumeQualityOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  checkVolume(output, "output");
  checkVolume(exemplar, "exemplar");
  if (output.channels != exemplar.channels)
    throw InputError("the output and the exemplar have different channel counts");
  if (o.patch <= 0 || o.patch % 2 == 0 || o.slicePatch <= 0 || o.slicePatch % 2 == 0)
    throw InputError("patch sides must be positive and odd");
  if (o.samples <= 0 || o.slicesPerAxis <= 0 || o.searchDims <= 0 || o.searchBudget <= 0)
    throw InputError("samples, slices, search dimensions and the search budget must be positive");
  const int p = o.patch, sp = o.slicePatch;
  if (!fits(output.dims, p, p, p) || !fits(exemplar.dims, p, p, p))
    throw InputError("a " + std::to_string(p) + "^3 patch does not fit in the output or the exemplar");
  for (int axis = 0; axis < 3; ++axis)
    for (const DenseVolume* v : {&output, &exemplar})
      if (!fits(axis == 0   ? Dims{v->dims.y, v->dims.z, 1}
                : axis == 1 ? Dims{v->dims.x, v->dims.z, 1}
                            : Dims{v->dims.x, v->dims.y, 1},
                sp, sp, 1))
        throw InputError("a " + std::to_string(sp) + "^2 slice patch does not fit in the slices");

  // Rounding slack of the search bound, per component. The lower bound exceeded the true distance by
  // at most 1e-7 per component in the tests (float coordinates; r from a difference of squares, worst
  // where r is near 0); 2e-3 of the value range leaves a wide margin at little cost.
  float range = 1;
  for (const DenseVolume* v : {&output, &exemplar})
    for (float x : v->values) range = std::max(range, std::abs(x));
  const float slack = 2e-3f * range;

  VolumeQuality q;
  const DenseVolume shuffledOutput = shuffled(output, deriveSeed(o.seed, 0));
  Similarity exact, shuffledExact;
  auto count = [](Similarity& into, const Similarity& s) {
    into.searches += s.searches;
    into.exact += s.exact;
  };
  {
    const std::vector<Similarity> s = compare(
        PatchSet({&exemplar}, p, p, p), {PatchSet({&output}, p, p, p), PatchSet({&shuffledOutput}, p, p, p)},
        o, slack, deriveSeed(o.seed, 1));
    q.coherence = s[0].coherence;
    q.completeness = s[0].completeness;
    q.shuffledCoherence = s[1].coherence;
    q.shuffledCompleteness = s[1].completeness;
    count(exact, s[0]);
    count(shuffledExact, s[1]);
  }
  for (int axis = 0; axis < 3; ++axis) {
    const std::vector<DenseVolume> e = slicesOf(exemplar, axis, o.slicesPerAxis),
                                   out = slicesOf(output, axis, o.slicesPerAxis),
                                   sh = slicesOf(shuffledOutput, axis, o.slicesPerAxis);
    const std::vector<Similarity> s =
        compare(PatchSet(pointers(e), sp, sp, 1),
                {PatchSet(pointers(out), sp, sp, 1), PatchSet(pointers(sh), sp, sp, 1)}, o, slack,
                deriveSeed(o.seed, 2, std::uint64_t(axis)));
    q.sliceCoherence[std::size_t(axis)] = s[0].coherence;
    q.sliceCompleteness[std::size_t(axis)] = s[0].completeness;
    q.shuffledSliceCoherence[std::size_t(axis)] = s[1].coherence;
    q.shuffledSliceCompleteness[std::size_t(axis)] = s[1].completeness;
    count(exact, s[0]);
    count(shuffledExact, s[1]);
  }
  q.exactShare = double(exact.exact) / double(std::max<std::int64_t>(exact.searches, 1));
  q.shuffledExactShare =
      double(shuffledExact.exact) / double(std::max<std::int64_t>(shuffledExact.searches, 1));
  q.valueWasserstein = valueWasserstein(output, exemplar);
  q.seconds = secondsSince(start);
  return q;
}

}  // namespace solidtex
