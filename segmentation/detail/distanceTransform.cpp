#include "segmentation/detail/distanceTransform.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace solidtex::segmentation::detail {
namespace {

constexpr float kFar = std::numeric_limits<float>::infinity();

// Distance to the nearest zero pixel in the same column, kFar when there is none: one sweep down,
// one up, a row at a time (cache-friendly). Values are integers up to 20000, exact in float.
void columnDistances(const cv::Mat& mask, cv::Mat& g) {
  for (int y = 0; y < mask.rows; ++y) {
    const uchar* m = mask.ptr<uchar>(y);
    const float* above = y > 0 ? g.ptr<float>(y - 1) : nullptr;
    float* d = g.ptr<float>(y);
    for (int x = 0; x < mask.cols; ++x) d[x] = m[x] == 0 ? 0.f : above ? above[x] + 1 : kFar;
  }
  for (int y = mask.rows - 2; y >= 0; --y) {
    const float* below = g.ptr<float>(y + 1);
    float* d = g.ptr<float>(y);
    for (int x = 0; x < mask.cols; ++x) d[x] = std::min(d[x], below[x] + 1);
  }
}

// Felzenszwalb & Huttenlocher's lower envelope of the parabolas (x - q)^2 + g(q)^2, in 64-bit
// integers: exact for any image side up to kMaxPhotoSide and far beyond. Columns without a zero
// pixel add no parabola.
class RowEnvelope {
public:
  explicit RowEnvelope(int width)
      : v_(std::size_t(width)), z_(std::size_t(width) + 1), f_(std::size_t(width)) {}

  // Replaces the column distances of one row by the Euclidean distances; returns false (row left
  // alone) when no column of the image holds a zero pixel.
  bool apply(float* row, int width) {
    if (!build(row, width)) return false;
    for (int x = 0, k = 0; x < width; ++x) {
      while (k + 1 < count_ && z_[std::size_t(k) + 1] < x) ++k;
      const std::int64_t q = v_[std::size_t(k)], dx = x - q;
      row[x] = float(std::sqrt(double(dx * dx + f_[std::size_t(q)])));
    }
    return true;
  }

private:
  bool build(const float* row, int width) {
    count_ = 0;
    for (int q = 0; q < width; ++q) {
      if (row[q] == kFar) continue;
      const auto g = std::int64_t(row[q]);
      f_[std::size_t(q)] = g * g;
      while (count_ > 0 && intersection(v_[std::size_t(count_) - 1], q) <= z_[std::size_t(count_) - 1])
        --count_;
      z_[std::size_t(count_)] = count_ == 0 ? -INFINITY : intersection(v_[std::size_t(count_) - 1], q);
      v_[std::size_t(count_++)] = q;
    }
    return count_ > 0;
  }

  // Where the parabolas of columns p < q cross. The numerator is an exact integer and IEEE
  // division rounds correctly, so equal crossings compare equal.
  double intersection(std::int64_t p, std::int64_t q) const {
    const std::int64_t numerator = f_[std::size_t(q)] + q * q - f_[std::size_t(p)] - p * p;
    return double(numerator) / double(2 * (q - p));
  }

  std::vector<int> v_;           // columns whose parabola is on the envelope
  std::vector<double> z_;        // where each of them starts to be the lowest
  std::vector<std::int64_t> f_;  // squared column distance per column
  int count_ = 0;
};

}  // namespace

cv::Mat euclideanDistance(const cv::Mat& mask) {
  CV_Assert(mask.type() == CV_8UC1);
  cv::Mat distance(mask.size(), CV_32F);
  columnDistances(mask, distance);
  const float nowhere = float(std::hypot(mask.cols, mask.rows));
  cv::parallel_for_(cv::Range(0, mask.rows), [&](const cv::Range& rows) {
    RowEnvelope envelope(mask.cols);
    for (int y = rows.start; y < rows.end; ++y)
      if (!envelope.apply(distance.ptr<float>(y), mask.cols)) distance.row(y).setTo(nowhere);
  });
  return distance;
}

}  // namespace solidtex::segmentation::detail
