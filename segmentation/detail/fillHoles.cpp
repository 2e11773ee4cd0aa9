#include "segmentation/detail/fillHoles.h"

#include <vector>

#include <opencv2/imgproc.hpp>

#include "segmentation/detail/shape.h"

namespace solidtex::segmentation::detail {
namespace {

constexpr int kNobody = 0, kSeveral = -1;

// The one particle bordering each background component, kNobody or kSeveral.
std::vector<int> soleNeighbours(const cv::Mat& labels, const cv::Mat& holes, int holeCount) {
  std::vector<int> owner(std::size_t(holeCount), kNobody);
  const auto meet = [&](int hole, int label) {
    int& o = owner[std::size_t(hole)];
    if (label > 0 && o != label) o = o == kNobody ? label : kSeveral;
  };
  for (int y = 0; y < labels.rows; ++y) {
    const int* h = holes.ptr<int>(y);
    const int* l = labels.ptr<int>(y);
    for (int x = 0; x < labels.cols; ++x) {
      if (h[x] == 0) continue;
      if (x > 0) meet(h[x], l[x - 1]);
      if (x + 1 < labels.cols) meet(h[x], l[x + 1]);
      if (y > 0) meet(h[x], labels.ptr<int>(y - 1)[x]);
      if (y + 1 < labels.rows) meet(h[x], labels.ptr<int>(y + 1)[x]);
    }
  }
  return owner;
}

}  // namespace

void fillEnclosedHoles(cv::Mat& labels) {
  CV_Assert(labels.type() == CV_32SC1);
  cv::Mat holes, stats, centroids;
  // 4-connected background: the dual of 8-connected particles.
  const int count = cv::connectedComponentsWithStats(labels == 0, holes, stats, centroids, 4, CV_32S);
  std::vector<int> owner = soleNeighbours(labels, holes, count);
  for (int i = 1; i < count; ++i) {
    const cv::Rect box(stats.at<int>(i, cv::CC_STAT_LEFT), stats.at<int>(i, cv::CC_STAT_TOP),
                       stats.at<int>(i, cv::CC_STAT_WIDTH), stats.at<int>(i, cv::CC_STAT_HEIGHT));
    if (touchesBorder(box, labels.size())) owner[std::size_t(i)] = kNobody;  // open to the outside
  }
  for (int y = 0; y < labels.rows; ++y) {
    const int* h = holes.ptr<int>(y);
    int* l = labels.ptr<int>(y);
    for (int x = 0; x < labels.cols; ++x)
      if (h[x] > 0 && owner[std::size_t(h[x])] > 0) l[x] = owner[std::size_t(h[x])];
  }
}

}  // namespace solidtex::segmentation::detail
