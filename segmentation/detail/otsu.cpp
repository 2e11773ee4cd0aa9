#include "segmentation/detail/otsu.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace solidtex::segmentation::detail {
namespace {

constexpr int kBins = 512;
constexpr int kRangeBins = 4096;  // resolution of the 0.1 % / 99.9 % quantiles

template <typename Visit>
void forEachValue(const cv::Mat& values, const cv::Mat& mask, Visit visit) {
  for (int y = 0; y < values.rows; ++y) {
    const float* v = values.ptr<float>(y);
    const uchar* m = mask.empty() ? nullptr : mask.ptr<uchar>(y);
    for (int x = 0; x < values.cols; ++x)
      if (!m || m[x]) visit(v[x]);
  }
}

struct Range {
  float lo = 0, hi = 0;
  double count = 0;
};

// The 0.1 % and 99.9 % quantiles, to a 1/kRangeBins of the full range.
Range robustRange(const cv::Mat& values, const cv::Mat& mask) {
  float lo = INFINITY, hi = -INFINITY;
  double count = 0;
  forEachValue(values, mask, [&](float v) { lo = std::min(lo, v), hi = std::max(hi, v), count += 1; });
  if (count < 2 || !(hi > lo)) return {lo, hi, count};
  std::vector<double> histogram(kRangeBins, 0);
  const double scale = kRangeBins / double(hi - lo);
  forEachValue(values, mask, [&](float v) {
    histogram[std::size_t(std::min(kRangeBins - 1, int((v - lo) * scale)))] += 1;
  });
  const auto quantile = [&](double q) {
    double seen = 0;
    for (int b = 0; b < kRangeBins; ++b)
      if ((seen += histogram[std::size_t(b)]) > q * count) return float(lo + b / scale);
    return hi;
  };
  return {quantile(0.001), std::max(quantile(0.999) + float(1 / scale), lo), count};
}

// Count, sum and sum of squares per bin over the robust range, and their totals.
struct Histogram {
  double lo = 0, binWidth = 0, n = 0, totalSum = 0, totalSq = 0;
  std::array<double, kBins> count{}, sum{}, sumSq{};
  double totalVariance() const { return totalSq / n - (totalSum / n) * (totalSum / n); }
};

// Empty (n < 2) when the values hold no range.
Histogram histogramOf(const cv::Mat& values, const cv::Mat& mask) {
  CV_Assert(values.type() == CV_32FC1 &&
            (mask.empty() || (mask.type() == CV_8UC1 && mask.size() == values.size())));
  const Range range = robustRange(values, mask);
  Histogram h;
  h.lo = range.lo;
  if (range.count < 2 || !(range.hi > range.lo)) return h;
  const double lo = range.lo, hi = range.hi;
  h.binWidth = (hi - lo) / kBins;
  h.n = range.count;
  forEachValue(values, mask, [&](float x) {
    const double c = std::clamp(double(x), lo, hi);
    const auto b = std::size_t(std::min(kBins - 1, int((c - lo) / h.binWidth)));
    h.count[b] += 1;
    h.sum[b] += c;
    h.sumSq[b] += c * c;
    h.totalSum += c;
    h.totalSq += c * c;
  });
  return h;
}

}  // namespace

OtsuSplit otsu(const cv::Mat& values, const cv::Mat& mask) {
  const Histogram h = histogramOf(values, mask);
  OtsuSplit best;
  best.threshold = float(h.lo);
  if (h.n < 2) return best;
  const double n = h.n, totalSum = h.totalSum, totalSq = h.totalSq, totalVar = h.totalVariance();
  double n0 = 0, s0 = 0, q0 = 0, bestBetween = -1;
  for (int b = 0; b + 1 < kBins; ++b) {
    n0 += h.count[std::size_t(b)];
    s0 += h.sum[std::size_t(b)];
    q0 += h.sumSq[std::size_t(b)];
    if (n0 <= 0 || n0 >= n) continue;
    const double n1 = n - n0, m0 = s0 / n0, m1 = (totalSum - s0) / n1;
    const double between = n0 * n1 / (n * n) * (m1 - m0) * (m1 - m0);
    if (between > bestBetween) {
      bestBetween = between;
      best = {float(h.lo + (b + 1) * h.binWidth),
              totalVar > 0 ? between / totalVar : 0.0,
              m0,
              m1,
              std::sqrt(std::max(0.0, q0 / n0 - m0 * m0)),
              std::sqrt(std::max(0.0, (totalSq - q0) / n1 - m1 * m1))};
    }
  }
  return best;
}

OtsuThreeClasses otsuThreeClasses(const cv::Mat& values, const cv::Mat& mask) {
  const Histogram h = histogramOf(values, mask);
  OtsuThreeClasses best{float(h.lo), float(h.lo), 0};
  if (h.n < 3) return best;
  // Prefix counts and sums: each class's share and mean in O(1), every split pair in O(bins^2).
  std::array<double, kBins + 1> n{}, s{};
  for (int b = 0; b < kBins; ++b) {
    n[std::size_t(b) + 1] = n[std::size_t(b)] + h.count[std::size_t(b)];
    s[std::size_t(b) + 1] = s[std::size_t(b)] + h.sum[std::size_t(b)];
  }
  const double mean = h.totalSum / h.n;
  const auto classTerm = [&](int from, int to) {  // bins [from, to)
    const double count = n[std::size_t(to)] - n[std::size_t(from)];
    if (count <= 0) return -1.0;
    const double m = (s[std::size_t(to)] - s[std::size_t(from)]) / count;
    return count * (m - mean) * (m - mean);
  };
  double bestBetween = -1;
  for (int i = 1; i + 1 < kBins; ++i) {
    const double low = classTerm(0, i);
    if (low < 0) continue;
    for (int j = i + 1; j < kBins; ++j) {
      const double middle = classTerm(i, j), high = classTerm(j, kBins);
      if (middle < 0 || high < 0) continue;
      if (low + middle + high > bestBetween) {
        bestBetween = low + middle + high;
        best.lower = float(h.lo + i * h.binWidth);
        best.upper = float(h.lo + j * h.binWidth);
      }
    }
  }
  const double totalVar = h.totalVariance();
  best.separability = bestBetween > 0 && totalVar > 0 ? bestBetween / h.n / totalVar : 0.0;
  return best;
}

}  // namespace solidtex::segmentation::detail
