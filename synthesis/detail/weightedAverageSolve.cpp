#include "synthesis/detail/weightedAverageSolve.h"

#include <cmath>

#include "synthesis/detail/VoxelBatches.h"

namespace solidtex::synthesis::detail {

void weightedAverageSolve(WorkVolume& volume, const RgbImage& exemplar, const ExemplarNeighborhoods& ex,
                          const SliceMatches& matches, const ChannelHistograms& exemplarHistogram,
                          ChannelHistograms& volumeHistogram, const WeightedAverageSettings& settings) {
  const int n = volume.n;
  const int W = exemplar.width;
  const double exponent = (settings.irlsExponent - 2.0) / 2.0;
  const double eps = settings.irlsEpsilon * ex.shape.dims();
  if (volume.source.size() != volume.count()) volume.source.assign(volume.count(), -1);
  std::vector<float> irls(matches.distance.size());
  tbb::parallel_for(std::size_t(0), irls.size(),
                    [&](std::size_t i) { irls[i] = float(std::pow(matches.distance[i] + eps, exponent)); });

  const std::vector<float> before = volume.rgb;
  for (int batch = 0; batch < kParityBatches; ++batch) {
    forEachVoxelInBatch(n, batch, [&](const std::array<int, 3>& v, std::size_t vi) {
      double sum[3] = {0, 0, 0}, total = 0, bestWeight = -1;
      std::int32_t dominant = -1;
      forEachCoveringCentre(matches.grid, ex.shape, v, [&](std::size_t id, int i, int j) {
        const std::int32_t m = matches.match[id];
        if (m < 0) return;
        const std::int32_t pixel = (ex.centreY(m) + j) * W + (ex.centreX(m) + i);
        const float* e = exemplar.data.data() + 3 * std::size_t(pixel);
        std::array<double, 3> hs, he;
        for (int c = 0; c < 3; ++c) {
          const int bin = volumeHistogram.binOf(e[c]);
          hs[c] = volumeHistogram.density(c, bin);
          he[c] = exemplarHistogram.density(c, bin);
        }
        const double w = colorHistogramWeight(irls[id], hs, he);
        for (int c = 0; c < 3; ++c) sum[c] += w * e[c];
        total += w;
        if (w > bestWeight) {
          bestWeight = w;
          dominant = pixel;
        }
      });
      if (total <= 0) return;
      float* out = volume.at(vi);
      for (int c = 0; c < 3; ++c) out[c] = float(sum[c] / total);
      volume.source[vi] = dominant;
    });
    forEachVoxelInBatchSequential(n, batch, [&](const std::array<int, 3>&, std::size_t vi) {
      volumeHistogram.add(before.data() + 3 * vi, -1);
      volumeHistogram.add(volume.at(vi), +1);
    });
  }
}

}  // namespace solidtex::synthesis::detail
