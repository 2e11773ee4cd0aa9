#include "synthesis/SliceMatches.h"

#include <limits>

#include <tbb/parallel_for.h>

#include "synthesis/Histograms.h"

namespace solidtex::synthesis {

namespace {

struct Scratch {
  Eigen::VectorXf full, centred, reduced;
};

inline float squaredDistance(const float* a, const float* b, int d) {
  float s = 0;
  for (int c = 0; c < d; ++c) {
    const float t = a[c] - b[c];
    s += t * t;
  }
  return s;
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
          const SliceAxes sa = sliceAxes(axis);
          const int R = settings.coherenceRadius;
          std::array<int, 3> u = c;
          for (int dj = -R; dj <= R; ++dj) {
            u[sa.w] = volume.wrap(c[sa.w] + dj);
            for (int di = -R; di <= R; ++di) {
              u[sa.u] = volume.wrap(c[sa.u] + di);
              const std::int32_t p = volume.source[volume.index(u[0], u[1], u[2])];
              const int px = p % ex.exemplarWidth, py = p / ex.exemplarWidth;
              const std::int32_t* set = settings.sets->of(ex.clampedIndexOf(px - di, py - dj));
              for (int q = 0; q < settings.sets->k; ++q) consider(set[q]);
            }
          }
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
