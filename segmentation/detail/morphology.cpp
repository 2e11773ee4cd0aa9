#include "segmentation/detail/morphology.h"

#include <vector>

#include <opencv2/imgproc.hpp>

namespace solidtex::segmentation::detail {
namespace {

// Sets the pixels of the components of `selected` smaller than minArea to `value` in `mask`.
void replaceSmall(const cv::Mat& selected, cv::Mat& mask, double minArea, int connectivity, uchar value) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(selected, labels, stats, centroids, connectivity, CV_32S);
  std::vector<char> small(std::size_t(n), 0);
  bool any = false;
  for (int i = 1; i < n; ++i) any |= (small[i] = stats.at<int>(i, cv::CC_STAT_AREA) < minArea) != 0;
  if (!any) return;
  for (int y = 0; y < mask.rows; ++y) {
    const int* l = labels.ptr<int>(y);
    uchar* m = mask.ptr<uchar>(y);
    for (int x = 0; x < mask.cols; ++x)
      if (small[std::size_t(l[x])]) m[x] = value;
  }
}

}  // namespace

void removeSmallComponents(cv::Mat& mask, double minArea) {
  CV_Assert(mask.type() == CV_8UC1);
  replaceSmall(mask, mask, minArea, 8, 0);
}

void fillSmallHoles(cv::Mat& mask, double minArea) {
  CV_Assert(mask.type() == CV_8UC1);
  // 4-connected holes are the dual of 8-connected particles.
  replaceSmall(mask == 0, mask, minArea, 4, 255);
}

}  // namespace solidtex::segmentation::detail
