#include "synthesis/detail/SliceMatches.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <tbb/parallel_for.h>

#include "synthesis/detail/histograms.h"

namespace solidtex::synthesis::detail {

namespace {

struct Scratch {
  Eigen::VectorXf full, centred, reduced;
  std::vector<std::int32_t> candidates;
};

/// Squared distance with four independent partial sums, so the compiler can keep them in one
/// vector register (a single running sum serialises every addition). Stops early, returning a
/// value above `bound`, once the partial sum exceeds `bound`: PCA coefficients come in decreasing
/// variance, so most candidates are rejected after a few blocks. The partial sums only grow (the
/// terms are non-negative and rounding is monotone), so a candidate is dropped only when its full
/// distance would exceed `bound` too, and a completed distance is the same value as without the bound.
inline float boundedSquaredDistance(const float* a, const float* b, int d, float bound) {
  float part[4] = {0, 0, 0, 0};
  int c = 0;
  for (; c + 4 <= d; c += 4) {
    for (int l = 0; l < 4; ++l) {
      const float t = a[c + l] - b[c + l];
      part[l] += t * t;
    }
    if (c >= 4 && (part[0] + part[1]) + (part[2] + part[3]) > bound)
      return (part[0] + part[1]) + (part[2] + part[3]);
  }
  float s = (part[0] + part[1]) + (part[2] + part[3]);
  for (; c < d; ++c) {
    const float t = a[c] - b[c];
    s += t * t;
  }
  return s;
}

/// k-coherence candidates of the slice neighbourhood at c: for every slice neighbour u within
/// `radius`, the similarity set of the exemplar neighbourhood that u's source pixel implies,
/// shifted back by u's offset. Each set is taken once: in coherent regions all neighbours imply
/// the same set. (Ids may still repeat across different sets; considering one twice is harmless.)
void coherenceCandidates(const WorkVolume& volume, const ExemplarNeighborhoods& ex, const AxisExemplars& axes,
                         const SimilaritySets& sets, int axis, const std::array<int, 3>& c, int radius,
                         std::vector<std::int32_t>& out) {
  // A neighbour may copy another plane's pixel: its row in this axis's plane stands in for it.
  const int top = ex.centreY(axes.first[axis]), bottom = ex.centreY(axes.end[axis] - 1);
  out.clear();
  const SliceAxes sa = sliceAxes(axis);
  std::array<int, 3> u = c;
  for (int dj = -radius; dj <= radius; ++dj) {
    u[sa.w] = volume.wrap(c[sa.w] + dj);
    for (int di = -radius; di <= radius; ++di) {
      u[sa.u] = volume.wrap(c[sa.u] + di);
      const std::int32_t p = volume.source[volume.index(u[0], u[1], u[2])];
      const int px = p % ex.exemplarWidth, py = axes.rowIn(axis, p / ex.exemplarWidth);
      const std::int32_t set = ex.clampedIndexOf(px - di, std::clamp(py - dj, top, bottom));
      if (std::find(out.begin(), out.end(), set) == out.end()) out.push_back(set);
    }
  }
  const std::size_t distinctSets = out.size();
  for (std::size_t q = 0; q < distinctSets; ++q) {
    const std::int32_t* set = sets.of(out[q]);
    out.insert(out.end(), set, set + sets.k);
  }
  out.erase(out.begin(), out.begin() + std::ptrdiff_t(distinctSets));
}

/// The best candidate of one slice neighbourhood under eq. 5-6: score = w_d * (distance + floor)
/// with w_d >= 1, or the bare distance without index histogram matching. Ties go to the smaller id,
/// so the winner does not depend on the order in which candidates are considered.
class BestCandidate {
public:
  BestCandidate(const float* query, int dims, const SearchSettings& settings, double floor,
                const std::vector<std::int64_t>& indexHistogram, std::int32_t previous)
      : query_(query),
        dims_(dims),
        settings_(settings),
        floor_(settings.phi ? floor : 0.0),
        indexHistogram_(indexHistogram),
        previous_(previous) {}

  void consider(int m, const float* coefficients) {
    const float distance = boundedSquaredDistance(query_, coefficients, dims_, bound_);
    if (distance > bound_) return;
    double score = distance;
    if (settings_.phi)
      score = indexHistogramDistance(
          score + floor_, settings_.histogramScale * (double(indexHistogram_[m]) - (m == previous_ ? 1 : 0)),
          settings_.histogramScale * (*settings_.phi)[m]);
    if (score < bestScore_ || (score == bestScore_ && m < best_)) {
      bestScore_ = score;
      best_ = m;
      // w_d >= 1, so a candidate whose bare distance exceeds this cannot win; rounded up, so
      // float rounding never drops one that could.
      bound_ = std::nextafter(float(bestScore_ - floor_), std::numeric_limits<float>::infinity());
    }
  }
  /// Largest bare squared distance that may still win.
  float bound() const { return bound_; }
  int best() const { return best_; }

private:
  const float* query_;
  int dims_;
  const SearchSettings& settings_;
  double floor_;
  const std::vector<std::int64_t>& indexHistogram_;
  std::int32_t previous_;
  int best_ = -1;
  double bestScore_ = std::numeric_limits<double>::infinity();
  float bound_ = std::numeric_limits<float>::infinity();
};

/// Exemplar neighbourhoods sorted by their first PCA coefficient (the largest-variance one), with
/// their coefficients copied in that order, for an exhaustive search that skips every
/// neighbourhood whose first coefficient alone puts it beyond the best score so far.
struct SortedByFirstCoefficient {
  std::vector<std::int32_t> id;
  std::vector<float> key;           ///< first coefficient, increasing
  std::vector<float> coefficients;  ///< in sorted order, d per neighbourhood

  /// Of neighbourhoods [first, end).
  SortedByFirstCoefficient(const ExemplarNeighborhoods& ex, int first, int end) {
    const int M = end - first, d = ex.reducedDims();
    id.resize(M);
    for (int m = 0; m < M; ++m) id[m] = first + m;
    std::stable_sort(id.begin(), id.end(),
                     [&](std::int32_t a, std::int32_t b) { return ex.reducedAt(a)[0] < ex.reducedAt(b)[0]; });
    key.resize(M);
    coefficients.resize(std::size_t(M) * d);
    for (int r = 0; r < M; ++r) {
      key[r] = ex.reducedAt(id[r])[0];
      std::copy(ex.reducedAt(id[r]), ex.reducedAt(id[r]) + d, coefficients.begin() + std::ptrdiff_t(r) * d);
    }
  }
};

/// Exhaustive search, exact: walks outwards from the query's first coefficient on both sides and
/// stops a side once the first coefficient's squared difference alone exceeds the bound (the
/// distance's partial sums include that term and only grow, and eq. 6 only enlarges distances).
void considerAll(const SortedByFirstCoefficient& sorted, int d, const float* y, BestCandidate& best) {
  const std::ptrdiff_t M = std::ptrdiff_t(sorted.id.size());
  std::ptrdiff_t up = std::lower_bound(sorted.key.begin(), sorted.key.end(), y[0]) - sorted.key.begin();
  std::ptrdiff_t down = up - 1;
  auto beyond = [&](std::ptrdiff_t r) {
    const float t = y[0] - sorted.key[r];
    return t * t > best.bound();
  };
  while (up < M || down >= 0) {
    if (up < M) {
      if (beyond(up))
        up = M;
      else
        best.consider(sorted.id[up], sorted.coefficients.data() + up * d), ++up;
    }
    if (down >= 0) {
      if (beyond(down))
        down = -1;
      else
        best.consider(sorted.id[down], sorted.coefficients.data() + down * d), --down;
    }
  }
}

}  // namespace

double searchPhase(const WorkVolume& volume, const ExemplarNeighborhoods& ex, const SearchSettings& settings,
                   SliceMatches& matches, std::vector<std::int64_t>& indexHistogram) {
  const SliceCentreGrid& grid = matches.grid;
  const std::size_t count = grid.count();
  const int D = ex.shape.dims();
  const int d = ex.reducedDims();
  const int M = ex.count();
  const Eigen::MatrixXf basisT = ex.pca.basis.transpose();
  // Eq. 5 multiplies the distance, which leaves exact matches (flat regions: distance 0) unaffected
  // and lets them all pile onto one index; a small floor keeps the weighting effective there.
  const double floor = settings.distanceFloor * D;
  if (indexHistogram.size() != std::size_t(M)) indexHistogram.assign(M, 0);
  const bool useSets = settings.sets && !settings.exhaustive && !volume.source.empty();
  const int batches = settings.phi ? std::max(1, settings.batches) : 1;
  std::vector<std::int32_t> previous = matches.match;
  const AxisExemplars axes = settings.axes ? *settings.axes : axisExemplarsOf(ex, 0);
  // Exhaustive levels are small (a few thousand neighbourhoods): sorting costs next to nothing.
  std::array<std::shared_ptr<const SortedByFirstCoefficient>, 3> sorted;
  for (int axis = 0; axis < 3; ++axis)
    if (settings.exhaustive || (!useSets && !settings.trees[axis]))
      sorted[axis] = axis > 0 && axes.first[axis] == axes.first[0] && sorted[0]
                         ? sorted[0]  // one exemplar for every axis: one list
                         : std::make_shared<SortedByFirstCoefficient>(ex, axes.first[axis], axes.end[axis]);

  for (int b = 0; b < batches; ++b) {
    const std::size_t inBatch = count > std::size_t(b) ? (count - b + batches - 1) / batches : 0;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, inBatch, 256),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        Scratch s;
                        s.full.resize(D);
                        s.reduced.resize(d);
                        for (std::size_t t = r.begin(); t != r.end(); ++t) {
                          const std::size_t id = std::size_t(b) + t * batches;
                          const int axis = grid.axisOf(id);
                          const std::array<int, 3> c = grid.voxelOf(id);
                          gatherSliceNeighborhood(volume, axis, c, ex.shape, s.full.data());
                          s.centred = s.full - ex.pca.mean;
                          s.reduced.noalias() = basisT * s.centred;
                          const float* y = s.reduced.data();

                          BestCandidate best(y, d, settings, floor, indexHistogram, previous[id]);
                          if (previous[id] >= 0) best.consider(previous[id], ex.reducedAt(previous[id]));
                          if (sorted[axis]) {
                            considerAll(*sorted[axis], d, y, best);
                          } else if (useSets) {
                            coherenceCandidates(volume, ex, axes, *settings.sets, axis, c,
                                                settings.coherenceRadius, s.candidates);
                            for (std::int32_t m : s.candidates) best.consider(m, ex.reducedAt(m));
                          } else {
                            const int m = axes.first[axis] + settings.trees[axis]->nearest(y);
                            best.consider(m, ex.reducedAt(m));
                          }
                          matches.match[id] = best.best();
                          matches.distance[id] = (s.full - ex.full.col(best.best())).squaredNorm();
                        }
                      });
    // Refresh the index histogram with this batch's new matches (integer counts: order-free).
    for (std::size_t id = b; id < count; id += batches) {
      if (previous[id] >= 0) --indexHistogram[previous[id]];
      ++indexHistogram[matches.match[id]];
    }
  }
  double sum = 0;
  for (std::size_t id = 0; id < count; ++id) sum += matches.distance[id];
  return count ? sum / double(count) / D : 0.0;
}

}  // namespace solidtex::synthesis::detail
