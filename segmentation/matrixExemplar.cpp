#include "segmentation/matrixExemplar.h"

#include <algorithm>
#include <vector>

#include <opencv2/imgproc.hpp>
#include <opencv2/xphoto.hpp>

#include "segmentation/detail/color.h"

namespace solidtex {
namespace {

// The top-left corner of the side x side window with the most non-zero pixels of `mask`, on a
// grid of `step` pixels (ties: the first in raster order).
cv::Point richestWindow(const cv::Mat& mask, int side, int step) {
  cv::Mat sums;
  cv::integral(mask / 255, sums, CV_32S);
  cv::Point best(0, 0);
  int bestCount = -1;
  for (int y = 0; y + side <= mask.rows; y += step)
    for (int x = 0; x + side <= mask.cols; x += step) {
      const int count = sums.at<int>(y + side, x + side) - sums.at<int>(y, x + side) -
                        sums.at<int>(y + side, x) + sums.at<int>(y, x);
      if (count > bestCount) bestCount = count, best = {x, y};
    }
  return best;
}

cv::Mat toLab8(const cv::Mat& linear) {
  cv::Mat srgb8, lab8;
  detail::linearToSrgb(linear).convertTo(srgb8, CV_8UC3, 255.0);
  cv::cvtColor(srgb8, lab8, cv::COLOR_RGB2Lab);
  return lab8;
}

cv::Mat fromLab8(const cv::Mat& lab8) {
  cv::Mat srgb8, srgb;
  cv::cvtColor(lab8, srgb8, cv::COLOR_Lab2RGB);
  srgb8.convertTo(srgb, CV_32FC3, 1.0 / 255);
  return srgb;
}

}  // namespace

cv::Mat matrixExemplar(const ExemplarStats& stats, const MatrixExemplarOptions& options) {
  const cv::Mat& background = stats.backgroundMask;
  const int side = std::min({options.maxSide, background.cols, background.rows});
  if (side < 8) return {};
  const cv::Rect window(richestWindow(background, side, 4), cv::Size(side, side));
  cv::Mat known;
  const int rim = 2 * options.rim + 1;
  cv::erode(background(window), known, cv::getStructuringElement(cv::MORPH_ELLIPSE, {rim, rim}), {-1, -1}, 1,
            cv::BORDER_REPLICATE);
  if (cv::countNonZero(known) < options.minMatrixShare * double(window.area())) return {};

  cv::Mat linear = stats.backgroundResidual(window) +
                   cv::Scalar(stats.backgroundColor[0], stats.backgroundColor[1], stats.backgroundColor[2]);
  linear.setTo(0, known == 0);
  cv::Mat lab8 = toLab8(cv::max(linear, 0.0)), filled;
  if (cv::countNonZero(known) == window.area()) return fromLab8(lab8);  // xphoto fails on no hole
  cv::xphoto::inpaint(lab8, known, filled, cv::xphoto::INPAINT_SHIFTMAP);
  // Shift-map leaves some pixels unwritten (Lab 0, 0, 0 in 8 bits), known ones among them: the
  // known pixels are put back, and a filled pixel outside the range of the known ones takes the
  // colours around it instead.
  lab8.copyTo(filled, known);
  std::vector<cv::Mat> known3, filled3;
  cv::split(lab8, known3);
  cv::split(filled, filled3);
  cv::Mat unreached = cv::Mat::zeros(known.size(), CV_8U);
  for (int c = 0; c < 3; ++c) {
    double lo, hi;
    cv::minMaxLoc(known3[std::size_t(c)], &lo, &hi, nullptr, nullptr, known);
    unreached |= (filled3[std::size_t(c)] < lo) | (filled3[std::size_t(c)] > hi);
  }
  unreached &= (known == 0);
  if (cv::countNonZero(unreached) > 0) cv::inpaint(filled, unreached, filled, 3, cv::INPAINT_TELEA);
  return fromLab8(filled);
}

}  // namespace solidtex
