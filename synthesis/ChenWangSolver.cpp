#include "synthesis/ChenWangSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "synthesis/Histograms.h"
#include "synthesis/VoxelBatches.h"

namespace solidtex::synthesis {

std::vector<std::int64_t> positionHistogramOf(const std::vector<std::int32_t>& source, int pixels) {
  std::vector<std::int64_t> h(pixels, 0);
  for (std::int32_t p : source)
    if (p >= 0) ++h[p];
  return h;
}

namespace {

struct Proposal {
  std::int32_t pixel;
  double weight;
};

} // namespace

void discreteSolve(WorkVolume& volume, const RgbImage& exemplar, const ExemplarNeighborhoods& ex, const SliceMatches& matches,
                   const std::vector<double>& theta, std::vector<std::int64_t>& positionHistogram, const DiscreteSolveSettings& settings) {
  const int n = volume.n;
  const int W = exemplar.width;
  const double exponent = (settings.irlsExponent - 2.0) / 2.0;  // on squared distances
  const double eps = settings.irlsEpsilon * ex.shape.dims();
  const double scale = settings.histogramScale;
  const double invBandwidth = 1.0 / settings.modeBandwidth;
  if (volume.source.size() != volume.count()) volume.source.assign(volume.count(), -1);
  // IRLS weight per matched neighbourhood, computed once.
  std::vector<float> irls(matches.distance.size());
  tbb::parallel_for(std::size_t(0), irls.size(), [&](std::size_t i) { irls[i] = float(std::pow(matches.distance[i] + eps, exponent)); });

  const std::vector<std::int32_t> before = volume.source;
  for (int batch = 0; batch < kParityBatches; ++batch) {
    forEachVoxelInBatch(n, batch, [&](const std::array<int, 3>& v, std::size_t vi) {
      thread_local std::vector<Proposal> proposals;
      proposals.clear();
      double sum[3] = {0, 0, 0}, total = 0;
      const std::int32_t current = volume.source[vi];
      forEachCoveringCentre(matches.grid, ex.shape, v, [&](std::size_t id, int i, int j) {
        const std::int32_t m = matches.match[id];
        if (m < 0) return;
        const std::int32_t pixel = (ex.centreY(m) + j) * W + (ex.centreX(m) + i);
        const double h = double(positionHistogram[pixel]) - (pixel == current ? 1 : 0);
        const double w = positionHistogramWeight(irls[id], scale * h, scale * theta[pixel]);
        const float* e = exemplar.data.data() + 3 * std::size_t(pixel);
        for (int c = 0; c < 3; ++c) sum[c] += w * e[c];
        total += w;
        proposals.push_back({pixel, w});
      });
      if (proposals.empty() || total <= 0) return;
      std::int32_t best = -1;
      if (settings.choice == DiscreteSolveSettings::Choice::LargestVote) {
        std::sort(proposals.begin(), proposals.end(), [](const Proposal& a, const Proposal& b) { return a.pixel < b.pixel; });
        double bestVote = -1;
        for (std::size_t a = 0; a < proposals.size();) {
          double vote = 0;
          std::size_t b = a;
          for (; b < proposals.size() && proposals[b].pixel == proposals[a].pixel; ++b) vote += proposals[b].weight;
          if (vote > bestVote) {
            bestVote = vote;
            best = proposals[a].pixel;
          }
          a = b;
        }
      } else if (settings.choice == DiscreteSolveSettings::Choice::ColourMode) {
        double bestVote = -1;
        for (const Proposal& a : proposals) {
          const float* ea = exemplar.data.data() + 3 * std::size_t(a.pixel);
          double vote = 0;
          for (const Proposal& b : proposals) {
            const float* eb = exemplar.data.data() + 3 * std::size_t(b.pixel);
            const double d = (ea[0] - eb[0]) * (ea[0] - eb[0]) + (ea[1] - eb[1]) * (ea[1] - eb[1]) + (ea[2] - eb[2]) * (ea[2] - eb[2]);
            vote += b.weight * std::exp(-d * invBandwidth);
          }
          vote += 1e-9 * a.weight;  // ties: the proposal's own weight
          if (vote > bestVote || (vote == bestVote && a.pixel < best)) {
            bestVote = vote;
            best = a.pixel;
          }
        }
      } else {
        const double mean[3] = {sum[0] / total, sum[1] / total, sum[2] / total};
        double bestDist = std::numeric_limits<double>::infinity(), bestWeight = -1;
        for (const Proposal& p : proposals) {
          const float* e = exemplar.data.data() + 3 * std::size_t(p.pixel);
          double dist = 0;
          for (int c = 0; c < 3; ++c) dist += (e[c] - mean[c]) * (e[c] - mean[c]);
          if (dist < bestDist || (dist == bestDist && (p.weight > bestWeight || (p.weight == bestWeight && p.pixel < best)))) {
            bestDist = dist;
            bestWeight = p.weight;
            best = p.pixel;
          }
        }
      }
      volume.source[vi] = best;
      const float* e = exemplar.data.data() + 3 * std::size_t(best);
      float* out = volume.at(vi);
      out[0] = e[0];
      out[1] = e[1];
      out[2] = e[2];
    });
    forEachVoxelInBatchSequential(n, batch, [&](const std::array<int, 3>&, std::size_t vi) {
      const std::int32_t now = volume.source[vi], old = before[vi];
      if (now == old) return;
      if (old >= 0) --positionHistogram[old];
      if (now >= 0) ++positionHistogram[now];
    });
  }
}

} // namespace solidtex::synthesis
