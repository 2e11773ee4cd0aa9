#include "synthesis/SliceMatches.h"

#include <algorithm>
#include <limits>

#include <tbb/parallel_for.h>

#include "synthesis/Histograms.h"

namespace solidtex::synthesis {

namespace {

struct Scratch {
  Eigen::VectorXf full, centred, reduced;
  std::vector<std::int32_t> candidates;
};

/// Squared distance with four independent partial sums, so the compiler can keep them in one
/// vector register (a single running sum serialises every addition).
inline float squaredDistance(const float* a, const float* b, int d) {
  float part[4] = {0, 0, 0, 0};
  int c = 0;
  for (; c + 4 <= d; c += 4)
    for (int l = 0; l < 4; ++l) {
      const float t = a[c + l] - b[c + l];
      part[l] += t * t;
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
void coherenceCandidates(const WorkVolume& volume, const ExemplarNeighborhoods& ex, const SimilaritySets& sets, int axis,
                         const std::array<int, 3>& c, int radius, std::vector<std::int32_t>& out) {
  out.clear();
  const SliceAxes sa = sliceAxes(axis);
  std::array<int, 3> u = c;
  for (int dj = -radius; dj <= radius; ++dj) {
    u[sa.w] = volume.wrap(c[sa.w] + dj);
    for (int di = -radius; di <= radius; ++di) {
      u[sa.u] = volume.wrap(c[sa.u] + di);
      const std::int32_t p = volume.source[volume.index(u[0], u[1], u[2])];
      const int px = p % ex.exemplarWidth, py = p / ex.exemplarWidth;
      const std::int32_t set = ex.clampedIndexOf(px - di, py - dj);
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

} // namespace

double searchPhase(const WorkVolume& volume, const ExemplarNeighborhoods& ex, const SearchSettings& settings, SliceMatches& matches,
                   std::vector<std::int64_t>& indexHistogram) {
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

  for (int b = 0; b < batches; ++b) {
    const std::size_t inBatch = count > std::size_t(b) ? (count - b + batches - 1) / batches : 0;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, inBatch, 256), [&](const tbb::blocked_range<std::size_t>& r) {
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

        int best = -1;
        double bestScore = std::numeric_limits<double>::infinity();
        auto consider = [&](int m) {
          double score = squaredDistance(y, ex.reducedAt(m), d);
          if (settings.phi)
            score = indexHistogramDistance(score + floor, settings.histogramScale * (double(indexHistogram[m]) - (m == previous[id] ? 1 : 0)),
                                           settings.histogramScale * (*settings.phi)[m]);
          if (score < bestScore || (score == bestScore && m < best)) {
            bestScore = score;
            best = m;
          }
        };
        if (previous[id] >= 0) consider(previous[id]);
        if (settings.exhaustive || (!useSets && !settings.tree)) {
          for (int m = 0; m < M; ++m) consider(m);
        } else if (useSets) {
          coherenceCandidates(volume, ex, *settings.sets, axis, c, settings.coherenceRadius, s.candidates);
          for (std::int32_t m : s.candidates) consider(m);
        } else {
          consider(settings.tree->nearest(y));
        }
        matches.match[id] = best;
        matches.distance[id] = (s.full - ex.full.col(best)).squaredNorm();
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

} // namespace solidtex::synthesis
