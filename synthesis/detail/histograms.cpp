#include "synthesis/detail/histograms.h"

#include <numeric>

namespace solidtex::synthesis::detail {

double colorHistogramWeight(double w, const std::array<double, 3>& synthesizedAtBins,
                            const std::array<double, 3>& exemplarAtBins) {
  double excess = 0;
  for (int j = 0; j < 3; ++j) excess += std::max(0.0, synthesizedAtBins[j] - exemplarAtBins[j]);
  return w / (1.0 + excess);
}

std::vector<double> expectedCounts(double total, std::size_t elements, const std::vector<float>& weights) {
  std::vector<double> out(elements, elements ? total / double(elements) : 0.0);
  if (weights.empty()) return out;
  const double sum = std::accumulate(weights.begin(), weights.end(), 0.0);
  if (sum <= 0) return out;
  for (std::size_t i = 0; i < elements; ++i) out[i] = total * double(weights[i]) / sum;
  return out;
}

ChannelHistograms::ChannelHistograms(int binCount) : bins(binCount) {
  for (auto& c : counts) c.assign(bins, 0);
}

void ChannelHistograms::add(const float* rgb, int delta) {
  for (int c = 0; c < 3; ++c) counts[c][binOf(rgb[c])] += delta;
  total += delta;
}

ChannelHistograms channelHistograms(const float* rgb, std::size_t count, int bins) {
  ChannelHistograms h(bins);
  for (std::size_t i = 0; i < count; ++i) h.add(rgb + 3 * i, 1);
  return h;
}

}  // namespace solidtex::synthesis::detail
