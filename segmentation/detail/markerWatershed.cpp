#include "segmentation/detail/markerWatershed.h"

#include <cstdint>
#include <functional>
#include <queue>
#include <vector>

namespace solidtex::segmentation::detail {
namespace {

struct Entry {
  float level;
  std::uint64_t order;  // insertion count: equal levels flood first-come first-served
  int index;
  bool operator>(const Entry& o) const { return level != o.level ? level > o.level : order > o.order; }
};

class Flooding {
public:
  Flooding(cv::Mat& labels, const cv::Mat& relief)
      : w_(labels.cols),
        h_(labels.rows),
        lab_(labels.ptr<uchar>()),
        lev_(relief.ptr<float>()),
        queued_(labels.total(), 0) {}

  void run() {
    for (int i = 0; i < w_ * h_; ++i)
      if (lab_[i] != 0) pushNeighbours(i);
    while (!queue_.empty()) {
      const Entry e = queue_.top();
      queue_.pop();
      lab_[e.index] = lowestLabelledNeighbour(e.index);
      pushNeighbours(e.index);
    }
  }

private:
  void neighbours(int i, int (&next)[4]) const {
    const int x = i % w_, y = i / w_;
    next[0] = x > 0 ? i - 1 : -1;
    next[1] = x + 1 < w_ ? i + 1 : -1;
    next[2] = y > 0 ? i - w_ : -1;
    next[3] = y + 1 < h_ ? i + w_ : -1;
  }

  // Where floods meet, the pixel joins the side it is reached from at the lowest level: the far
  // side of a crest only touches it from higher up.
  uchar lowestLabelledNeighbour(int i) const {
    int next[4];
    neighbours(i, next);
    int best = -1;
    for (int n : next)
      if (n >= 0 && lab_[n] != 0 && (best < 0 || lev_[n] < lev_[best])) best = n;
    return lab_[best];
  }

  void pushNeighbours(int i) {
    int next[4];
    neighbours(i, next);
    for (int n : next) {
      if (n < 0 || lab_[n] != 0 || queued_[std::size_t(n)]) continue;
      queued_[std::size_t(n)] = 1;
      queue_.push({lev_[n], order_++, n});
    }
  }

  int w_, h_;
  uchar* lab_;
  const float* lev_;
  std::vector<char> queued_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue_;
  std::uint64_t order_ = 0;
};

}  // namespace

cv::Mat markerWatershed(const cv::Mat& markers, const cv::Mat& relief) {
  CV_Assert(markers.type() == CV_8UC1 && relief.type() == CV_32FC1 && markers.size() == relief.size());
  cv::Mat labels = markers.clone();
  const cv::Mat level = relief.isContinuous() ? relief : relief.clone();
  Flooding(labels, level).run();
  return labels;
}

}  // namespace solidtex::segmentation::detail
