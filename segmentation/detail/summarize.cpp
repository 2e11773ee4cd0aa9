#include "segmentation/detail/summarize.h"

#include <algorithm>
#include <map>
#include <utility>

namespace solidtex::segmentation::detail {

AreaHistogram buildAreaHistogram(const std::vector<const Particle2D*>& particles) {
  AreaHistogram h;
  if (particles.empty()) return h;
  const auto [lo, hi] =
      std::minmax_element(particles.begin(), particles.end(),
                          [](const Particle2D* a, const Particle2D* b) { return a->area < b->area; });
  const double low = (*lo)->area;
  // All particles of one area still need ten increasing edges; they then fill the first bin.
  const double width = std::max((*hi)->area - low, 1.0) / 10.0;
  for (int i = 0; i <= 10; ++i) h.edges[std::size_t(i)] = low + i * width;
  h.edges[10] = std::max((*hi)->area, h.edges[10]);
  for (const Particle2D* p : particles) ++h.counts[std::size_t(h.binOf(p->area))];
  for (int i = 0; i < 10; ++i)
    h.ratios[std::size_t(i)] = double(h.counts[std::size_t(i)]) / double(particles.size());
  return h;
}

std::vector<SizePair> buildSizePairs(const std::vector<const Particle2D*>& particles) {
  std::map<std::pair<int, int>, int> counts;
  for (const Particle2D* p : particles) ++counts[{p->box.width, p->box.height}];
  std::vector<SizePair> pairs;
  pairs.reserve(counts.size());
  for (const auto& [size, count] : counts) pairs.push_back({size.first, size.second, count});
  return pairs;
}

}  // namespace solidtex::segmentation::detail
