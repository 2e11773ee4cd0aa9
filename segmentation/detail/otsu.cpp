#include "segmentation/detail/otsu.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace solidtex::detail {
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

}  // namespace

OtsuSplit otsu(const cv::Mat& values, const cv::Mat& mask) {
  CV_Assert(values.type() == CV_32FC1 &&
            (mask.empty() || (mask.type() == CV_8UC1 && mask.size() == values.size())));
  const Range range = robustRange(values, mask);
  OtsuSplit best;
  best.threshold = range.lo;
  if (range.count < 2 || !(range.hi > range.lo)) return best;
  const double lo = range.lo, hi = range.hi, binWidth = (hi - lo) / kBins;
  std::array<double, kBins> count{}, sum{}, sumSq{};
  double totalSum = 0, totalSq = 0;
  forEachValue(values, mask, [&](float x) {
    const double c = std::clamp(double(x), lo, hi);
    const int b = std::min(kBins - 1, int((c - lo) / binWidth));
    count[std::size_t(b)] += 1;
    sum[std::size_t(b)] += c;
    sumSq[std::size_t(b)] += c * c;
    totalSum += c;
    totalSq += c * c;
  });
  const double n = range.count, mean = totalSum / n, totalVar = totalSq / n - mean * mean;
  double n0 = 0, s0 = 0, q0 = 0, bestBetween = -1;
  for (int b = 0; b + 1 < kBins; ++b) {
    n0 += count[std::size_t(b)];
    s0 += sum[std::size_t(b)];
    q0 += sumSq[std::size_t(b)];
    if (n0 <= 0 || n0 >= n) continue;
    const double n1 = n - n0, m0 = s0 / n0, m1 = (totalSum - s0) / n1;
    const double between = n0 * n1 / (n * n) * (m1 - m0) * (m1 - m0);
    if (between > bestBetween) {
      bestBetween = between;
      best = {float(lo + (b + 1) * binWidth),
              totalVar > 0 ? between / totalVar : 0.0,
              m0,
              m1,
              std::sqrt(std::max(0.0, q0 / n0 - m0 * m0)),
              std::sqrt(std::max(0.0, (totalSq - q0) / n1 - m1 * m1))};
    }
  }
  return best;
}

}  // namespace solidtex::detail
