#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace solidtex::synthesis::detail {

/// Chen–Wang eq. 3 (Kopf et al.'s colour histogram re-weighting):
/// w' = w / (1 + sum_j max(0, Hs_j(b_j(e)) - He_j(b_j(e)))), given for each histogram j the value
/// of the synthesised and of the exemplar histogram at the bin holding e.
double colorHistogramWeight(double w, const std::array<double, 3>& synthesizedAtBins,
                            const std::array<double, 3>& exemplarAtBins);

/// Chen–Wang eq. 4 (position histogram re-weighting): w' = w / (1 + max(0, H(p(e)) - theta)),
/// H the number of voxels copying pixel p, theta that number were all pixels used evenly
/// (or the control map's theta(p)).
inline double positionHistogramWeight(double w, double h, double theta) {
  return w / (1.0 + std::max(0.0, h - theta));
}

/// Chen–Wang eq. 6: w_d = 1 + max(0, H(i(e)) - phi), H the number of slice neighbourhoods whose
/// nearest exemplar neighbourhood is i, phi that number were all indices used evenly.
inline double indexHistogramWeight(double h, double phi) { return 1.0 + std::max(0.0, h - phi); }

/// Chen–Wang eq. 5: the search distance d = w_d * ||s - e||^2.
inline double indexHistogramDistance(double squaredDistance, double h, double phi) {
  return indexHistogramWeight(h, phi) * squaredDistance;
}

/// Expected count per element (theta(p) or phi(i)) when `total` items spread over `elements`
/// elements in proportion to `weights` (a control map; evenly when empty).
std::vector<double> expectedCounts(double total, std::size_t elements,
                                   const std::vector<float>& weights = {});

/// Three per-channel histograms of RGB values in [0,1] with `bins` bins each, as counts.
struct ChannelHistograms {
  int bins = 16;
  std::array<std::vector<std::int64_t>, 3> counts;
  std::int64_t total = 0;

  explicit ChannelHistograms(int binCount = 16);
  int binOf(float v) const { return std::clamp(int(v * float(bins)), 0, bins - 1); }
  /// Adds (delta = +1) or removes (-1) one colour.
  void add(const float* rgb, int delta);
  /// The histogram value used in eq. 3: the bin's share of all values times the bin count
  /// (1 = as in a flat histogram), so excesses are comparable across bin counts.
  double density(int channel, int bin) const {
    return total ? double(counts[channel][bin]) * bins / double(total) : 0.0;
  }
};

/// Histograms of `count` interleaved RGB colours.
ChannelHistograms channelHistograms(const float* rgb, std::size_t count, int bins);

}  // namespace solidtex::synthesis::detail
