#include "segmentation/detail/morphology.h"

#include <algorithm>
#include <array>
#include <cmath>
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

cv::Mat crossMedian(const cv::Mat& image) {
  CV_Assert(image.type() == CV_32FC1);
  cv::Mat padded, out(image.size(), CV_32FC1);
  cv::copyMakeBorder(image, padded, 1, 1, 1, 1, cv::BORDER_REPLICATE);
  for (int y = 0; y < image.rows; ++y) {
    const float* above = padded.ptr<float>(y) + 1;
    const float* row = padded.ptr<float>(y + 1) + 1;
    const float* below = padded.ptr<float>(y + 2) + 1;
    float* o = out.ptr<float>(y);
    for (int x = 0; x < image.cols; ++x) {
      std::array<float, 5> v{row[x - 1], row[x], row[x + 1], above[x], below[x]};
      std::nth_element(v.begin(), v.begin() + 2, v.end());
      o[x] = v[2];
    }
  }
  return out;
}

void restoreCorners(cv::Mat& mask, const cv::Mat& distance) {
  constexpr double kClearly = 0.25;  // of the step from the outside pair's mean to the inside pair's
  CV_Assert(mask.type() == CV_8UC1 && distance.type() == CV_32FC1 && mask.size() == distance.size());
  const cv::Mat before = mask.clone();
  for (int y = 1; y + 1 < mask.rows; ++y)
    for (int x = 1; x + 1 < mask.cols; ++x) {
      const cv::Point side[4] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
      bool in[4];
      double sums[2] = {0, 0};
      int inside = 0;
      for (int i = 0; i < 4; ++i) {
        in[i] = before.at<uchar>(side[i]) != 0;
        inside += in[i];
        sums[in[i]] += distance.at<float>(side[i]);
      }
      if (inside != 2 || in[0] == in[1]) continue;  // a corner has one of each opposite pair inside
      const double step = (sums[1] - sums[0]) / 2;
      if (!(step > 0)) continue;  // no edge to read the pixel against
      // Where along the step from the outside pair's mean to the inside pair's: only a pixel that
      // clearly reads as the other side moves, so that a soft edge stays where it was drawn.
      const double along = (distance.at<float>(y, x) - sums[0] / 2) / step;
      if (!(std::abs(along - 0.5) > kClearly)) continue;  // NaN too: no reading
      mask.at<uchar>(y, x) = along > 0.5 ? 255 : 0;
    }
}

}  // namespace solidtex::segmentation::detail
