#include "segmentation/detail/splitParticles.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "segmentation/detail/distanceTransform.h"
#include "segmentation/detail/mergeConvex.h"

namespace solidtex::segmentation::detail {
namespace {

// Two peaks stay separate when the saddle between them lies at least this share of the smaller
// peak's height below it, i.e. the neck is under 85 % as wide as the smaller body. A generous
// rule: mergeWhereMoreConvex undoes the cuts that do not give more convex bodies ...
constexpr float kRelativeDepth = 0.15f;
// ... and at least this many pixels below it, because the discrete distance transform has
// sub-pixel ripples along straight ridges.
constexpr float kMinDepth = 1.0f;

bool keepApart(float smallerPeak, float saddle) {
  return smallerPeak - saddle >= std::max(kMinDepth, kRelativeDepth * smallerPeak);
}

class Basins {
public:
  int add(float peak) {
    parent_.push_back(int(parent_.size()));
    peak_.push_back(peak);
    return parent_.back();
  }
  int find(int b) {
    while (parent_[std::size_t(b)] != b)
      b = parent_[std::size_t(b)] = parent_[std::size_t(parent_[std::size_t(b)])];
    return b;
  }
  float peak(int b) const { return peak_[std::size_t(b)]; }
  std::size_t size() const { return parent_.size(); }
  // `into` has the higher peak, so the merged basin keeps it.
  void merge(int into, int from) { parent_[std::size_t(from)] = into; }

private:
  std::vector<int> parent_;
  std::vector<float> peak_;
};

struct Flood {
  const cv::Mat& dist;
  std::vector<int> basin;  // per pixel, -1 until flooded
  Basins basins;

  explicit Flood(const cv::Mat& d) : dist(d), basin(d.total(), -1) {}

  void visit(int index) {
    const int x = index % dist.cols, y = index / dist.cols;
    const float level = dist.at<float>(y, x);
    int roots[8], count = 0, steepest = -1;
    float steepestLevel = -1;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= dist.cols || ny >= dist.rows) continue;
        const int n = ny * dist.cols + nx;
        if (basin[std::size_t(n)] < 0) continue;
        roots[count++] = basins.find(basin[std::size_t(n)]);
        if (dist.at<float>(ny, nx) > steepestLevel) steepestLevel = dist.at<float>(ny, nx), steepest = n;
      }
    if (count == 0) {
      basin[std::size_t(index)] = basins.add(level);
      return;
    }
    mergeAt(roots, count, level);
    basin[std::size_t(index)] = basins.find(basin[std::size_t(steepest)]);
  }

  // The first time two basins touch is at their highest saddle: decide there.
  void mergeAt(int* roots, int count, float saddle) {
    const auto before = [&](int a, int b) {
      return basins.peak(a) != basins.peak(b) ? basins.peak(a) > basins.peak(b) : a < b;
    };
    // At most 8 entries: an insertion sort, which also lets GCC see the bounds.
    for (int i = 1; i < count; ++i)
      for (int j = i; j > 0 && before(roots[j], roots[j - 1]); --j) std::swap(roots[j], roots[j - 1]);
    count = int(std::unique(roots, roots + count) - roots);
    for (int i = 1; i < count; ++i)
      if (!keepApart(basins.peak(roots[i]), saddle)) basins.merge(basins.find(roots[0]), roots[i]);
  }
};

// Pixels inside the mask, highest distance first, ties in raster order. Non-negative floats
// order like their bit patterns, so one 64-bit key (inverted distance bits, then index) sorts
// without an indirect comparison.
std::vector<int> floodOrder(const cv::Mat& dist) {
  std::vector<std::uint64_t> keys;
  keys.reserve(dist.total());
  const float* d = dist.ptr<float>();
  for (int i = 0; i < int(dist.total()); ++i) {
    if (d[i] <= 0) continue;
    std::uint32_t bits;
    std::memcpy(&bits, &d[i], sizeof bits);
    keys.push_back((std::uint64_t(~bits) << 32) | std::uint32_t(i));
  }
  std::sort(keys.begin(), keys.end());
  std::vector<int> order(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) order[k] = int(keys[k] & 0xffffffffu);
  return order;
}

cv::Mat relabel(Flood& flood, const cv::Size& size) {
  cv::Mat labels = cv::Mat::zeros(size, CV_32S);
  std::vector<int> id(flood.basins.size(), 0);
  int next = 0;
  for (std::size_t i = 0; i < flood.basin.size(); ++i) {
    if (flood.basin[i] < 0) continue;
    int& label = id[std::size_t(flood.basins.find(flood.basin[i]))];
    if (label == 0) label = ++next;
    labels.at<int>(int(i) / size.width, int(i) % size.width) = label;
  }
  return labels;
}

}  // namespace

cv::Mat labelParticles(const cv::Mat& mask, bool split) {
  CV_Assert(mask.type() == CV_8UC1);
  cv::Mat labels;
  if (!split) {
    cv::connectedComponents(mask, labels, 8, CV_32S);
    return labels;
  }
  const cv::Mat dist = euclideanDistance(mask);
  CV_Assert(dist.isContinuous());
  Flood flood(dist);
  for (int index : floodOrder(dist)) flood.visit(index);
  labels = relabel(flood, mask.size());
  mergeWhereMoreConvex(labels);
  return labels;
}

}  // namespace solidtex::segmentation::detail
