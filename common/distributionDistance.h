#pragma once
/// @file
/// Summaries of, and distances between, empirical distributions on the line.

#include <algorithm>
#include <cmath>
#include <vector>

namespace solidtex {

/// Arithmetic mean; 0 for no values.
inline double mean(const std::vector<double>& values) {
  double sum = 0;
  for (double v : values) sum += v;
  return values.empty() ? 0 : sum / double(values.size());
}

/// The q-quantile (0 <= q <= 1) of sorted values, interpolating linearly between order statistics;
/// 0 for no values.
inline double quantileOfSorted(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0;
  const double at = std::clamp(q, 0.0, 1.0) * double(sorted.size() - 1);
  const std::size_t below = std::size_t(at);
  const double above = below + 1 < sorted.size() ? sorted[below + 1] : sorted[below];
  return sorted[below] + (at - double(below)) * (above - sorted[below]);
}

/// The empirical CDF of `values` at each of `at`: the share of values at or below it.
inline std::vector<double> empiricalCdfAt(std::vector<double> values, const std::vector<double>& at) {
  std::sort(values.begin(), values.end());
  std::vector<double> cdf;
  cdf.reserve(at.size());
  for (double x : at)
    cdf.push_back(values.empty()
                      ? 0.0
                      : double(std::upper_bound(values.begin(), values.end(), x) - values.begin()) /
                            double(values.size()));
  return cdf;
}

/// A pointwise percentile band of curves of one length (one per bootstrap resample): per point, the
/// `low` and `high` quantiles of the curves' values there.
struct PercentileBand {
  std::vector<double> low, high;
};

inline PercentileBand percentileBand(const std::vector<std::vector<double>>& curves, double low,
                                     double high) {
  PercentileBand band;
  if (curves.empty()) return band;
  std::vector<double> at(curves.size());
  for (std::size_t point = 0; point < curves.front().size(); ++point) {
    for (std::size_t c = 0; c < curves.size(); ++c) at[c] = curves[c][point];
    std::sort(at.begin(), at.end());
    band.low.push_back(quantileOfSorted(at, low));
    band.high.push_back(quantileOfSorted(at, high));
  }
  return band;
}

/// Two-sample Kolmogorov-Smirnov statistic: the largest gap between the empirical CDFs; 1 when
/// either sample is empty.
inline double ksStatistic(std::vector<double> a, std::vector<double> b) {
  if (a.empty() || b.empty()) return 1;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  std::size_t i = 0, j = 0;
  double gap = 0;
  while (i < a.size() && j < b.size()) {
    const double x = std::min(a[i], b[j]);
    while (i < a.size() && a[i] <= x) ++i;
    while (j < b.size() && b[j] <= x) ++j;
    gap = std::max(gap, std::abs(double(i) / double(a.size()) - double(j) / double(b.size())));
  }
  return gap;
}

/// Kuiper's two-sample statistic, the KS of values on a circle (angles, directions): the largest
/// gap of the empirical CDFs one way plus the largest the other way, which does not depend on where
/// the circle is cut; 1 when either sample is empty.
inline double kuiperStatistic(std::vector<double> a, std::vector<double> b) {
  if (a.empty() || b.empty()) return 1;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  std::size_t i = 0, j = 0;
  double above = 0, below = 0;
  while (i < a.size() && j < b.size()) {
    const double x = std::min(a[i], b[j]);
    while (i < a.size() && a[i] <= x) ++i;
    while (j < b.size() && b[j] <= x) ++j;
    const double gap = double(i) / double(a.size()) - double(j) / double(b.size());
    above = std::max(above, gap);
    below = std::max(below, -gap);
  }
  return above + below;
}

/// The two-sample KS statistic that samples of n and m values from one distribution exceed with
/// probability 0.05 (asymptotic: 1.358 sqrt((n + m) / (n m))): a KS below it is no evidence that the
/// distributions differ. 1 when either sample is empty.
inline double ksCritical95(std::size_t n, std::size_t m) {
  if (n == 0 || m == 0) return 1;
  return std::min(1.0, 1.358 * std::sqrt(double(n + m) / (double(n) * double(m))));
}

/// Wasserstein-1 (earth mover's) distance; 0 when either sample is empty.
inline double wasserstein1(std::vector<double> a, std::vector<double> b) {
  if (a.empty() || b.empty()) return 0;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  // Integrate |F_a - F_b| over the merged breakpoints.
  std::size_t i = 0, j = 0;
  double x = std::min(a.front(), b.front()), distance = 0;
  while (i < a.size() || j < b.size()) {
    const double next = j >= b.size() || (i < a.size() && a[i] <= b[j]) ? a[i] : b[j];
    distance += std::abs(double(i) / double(a.size()) - double(j) / double(b.size())) * (next - x);
    x = next;
    while (i < a.size() && a[i] <= x) ++i;
    while (j < b.size() && b[j] <= x) ++j;
  }
  return distance;
}

}  // namespace solidtex
