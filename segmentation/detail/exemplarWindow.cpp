#include "segmentation/detail/exemplarWindow.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

#include <opencv2/imgproc.hpp>
#include <opencv2/photo.hpp>

#include "segmentation/detail/color.h"

namespace solidtex::segmentation::detail {
namespace {

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
  linearToSrgb(cv::max(linear, 0.0)).convertTo(srgb8, CV_8UC3, 255.0);
  cv::cvtColor(srgb8, lab8, cv::COLOR_RGB2Lab);
  return lab8;
}

cv::Mat fromLab8(const cv::Mat& lab8) {
  cv::Mat srgb8, srgb;
  cv::cvtColor(lab8, srgb8, cv::COLOR_Lab2RGB);
  srgb8.convertTo(srgb, CV_32FC3, 1.0 / 255);
  return srgb;
}

cv::Mat weights3(const cv::Mat& mask) {
  cv::Mat one, three;
  mask.convertTo(one, CV_32F, 1.0 / 255);
  cv::merge(std::vector<cv::Mat>{one, one, one}, three);
  return three;
}

// The place whose pixels under `hole` are all known and whose pixels under `ring` agree best with
// `patch` (sum of squared Lab differences), if any (ties: the first in raster order).
std::optional<cv::Point> bestSource(const cv::Mat& labF, const cv::Mat& unknownF, const cv::Mat& patch,
                                    const cv::Mat& hole, const cv::Mat& ring) {
  cv::Mat holeF, unknownUnder, cost;
  hole.convertTo(holeF, CV_32F, 1.0 / 255);
  cv::matchTemplate(unknownF, holeF, unknownUnder, cv::TM_CCORR);
  cv::matchTemplate(labF, patch, cost, cv::TM_SQDIFF, weights3(ring));
  std::optional<cv::Point> best;
  float bestCost = std::numeric_limits<float>::infinity();
  for (int y = 0; y < cost.rows; ++y)
    for (int x = 0; x < cost.cols; ++x)
      if (unknownUnder.at<float>(y, x) < 0.5f && cost.at<float>(y, x) < bestCost)
        bestCost = cost.at<float>(y, x), best = cv::Point(x, y);
  return best;
}

// Small cells, rather than whole holes, find matching pieces even in a crowded photo. Pieces come
// from `area` of the photo.
void fillFromMatchingPieces(const cv::Mat& lab8, const cv::Mat& known, const cv::Rect& window,
                            const cv::Rect& area, cv::Mat& filled, cv::Mat& unfilled) {
  constexpr int kCell = 8, kRing = 2;
  cv::Mat labF, unknownF, filledF;
  lab8(area).convertTo(labF, CV_32FC3);
  cv::Mat(known(area) == 0).convertTo(unknownF, CV_32F, 1.0 / 255);
  const cv::Rect inside(0, 0, window.width, window.height);
  const cv::Mat ringShape = cv::getStructuringElement(cv::MORPH_RECT, {2 * kRing + 1, 2 * kRing + 1});
  for (bool progress = true; progress && cv::countNonZero(unfilled) > 0;) {
    progress = false;
    for (int y = 0; y < window.height; y += kCell)
      for (int x = 0; x < window.width; x += kCell) {
        const cv::Rect cell = cv::Rect(x, y, kCell, kCell) & inside;
        if (cv::countNonZero(unfilled(cell)) == 0) continue;
        const cv::Rect box = cv::Rect(x - kRing, y - kRing, kCell + 2 * kRing, kCell + 2 * kRing) & inside;
        cv::Mat hole = cv::Mat::zeros(box.size(), CV_8U), ring;
        unfilled(cell).copyTo(hole(cell - box.tl()));
        cv::dilate(hole, ring, ringShape);
        ring &= (unfilled(box) == 0);
        if (cv::countNonZero(ring) == 0) continue;  // inside the hole: once its edge is filled
        filled(box).convertTo(filledF, CV_32FC3);
        const std::optional<cv::Point> source = bestSource(labF, unknownF, filledF, hole, ring);
        if (!source) continue;
        const cv::Mat from = labF(cv::Rect(*source, box.size()));
        cv::Mat piece;
        cv::Mat(from + (cv::mean(filledF, ring) - cv::mean(from, ring))).convertTo(piece, CV_8UC3);
        piece.copyTo(filled(box), hole);
        unfilled(box).setTo(0, hole);
        progress = true;
      }
  }
}

}  // namespace

cv::Mat exemplarWindow(const cv::Mat& linear, const cv::Mat& known, int side, double minShare) {
  side = std::min({side, linear.cols, linear.rows});
  if (side < 8) return {};
  const cv::Rect window(richestWindow(known, side, 4), cv::Size(side, side));
  if (cv::countNonZero(known(window)) < minShare * double(window.area())) return {};
  cv::Mat knownLinear = linear.clone();
  knownLinear.setTo(0, known == 0);
  const cv::Mat lab8 = toLab8(knownLinear);
  cv::Mat filled = lab8(window).clone();
  cv::Mat unfilled = known(window) == 0;
  // Pieces from around the window first (a side's width each way: near enough to share its light),
  // then from anywhere in the photo.
  const cv::Rect photo(0, 0, lab8.cols, lab8.rows);
  const cv::Rect around =
      cv::Rect(window.x - window.width, window.y - window.height, 3 * window.width, 3 * window.height) &
      photo;
  fillFromMatchingPieces(lab8, known, window, around, filled, unfilled);
  if (around != photo && cv::countNonZero(unfilled) > 0)
    fillFromMatchingPieces(lab8, known, window, photo, filled, unfilled);
  if (cv::countNonZero(unfilled) > 0) cv::inpaint(filled, unfilled, filled, 3, cv::INPAINT_TELEA);
  return fromLab8(filled);
}

}  // namespace solidtex::segmentation::detail
