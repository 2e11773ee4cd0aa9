#include "segmentation/detail/separateBackground.h"

#include <array>
#include <cmath>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "segmentation/detail/chooseBackground.h"
#include "segmentation/detail/color.h"
#include "segmentation/detail/edgeDecision.h"
#include "segmentation/detail/flattenShading.h"
#include "segmentation/detail/morphology.h"
#include "segmentation/detail/otsu.h"

namespace solidtex::detail {
namespace {

constexpr double kMinSpread = 1.0;    // Lab units: a feature flatter than this carries no classes
constexpr double kMinContrast = 5.0;  // Delta E between the class means: below it, no visible classes
constexpr int kChroma = 3;            // feature index after L, a, b

// The feature that separates the classes best, and on which side of it the background lies.
struct Axis {
  int feature = -1;  // 0..2: L, a, b; kChroma: chroma
  float threshold = 0;
  bool backgroundAbove = false;
  bool valid() const { return feature >= 0; }
};

std::array<cv::Mat, 4> features(const cv::Mat& lab) {
  std::array<cv::Mat, 4> f;
  cv::split(lab, f.data());
  cv::magnitude(f[1], f[2], f[kChroma]);
  return f;
}

// Which feature carries the classes depends on the photo (grey coins, coloured candies on white),
// so each is tried and the most clearly bimodal one (highest Otsu separability) wins.
Axis bestAxis(const std::array<cv::Mat, 4>& f) {
  Axis best;
  double bestSeparability = -1;
  for (int k = 0; k < int(f.size()); ++k) {
    cv::Scalar mean, stddev;
    cv::meanStdDev(f[std::size_t(k)], mean, stddev);
    if (stddev[0] < kMinSpread) continue;
    const OtsuSplit split = otsu(f[std::size_t(k)]);
    if (split.separability > bestSeparability) {
      bestSeparability = split.separability;
      best = {k, split.threshold, false};
    }
  }
  return best;
}

// Pixels next to a class boundary mix both colours; leave them out of background estimates.
cv::Mat interior(const cv::Mat& mask) {
  cv::Mat inner;
  cv::erode(mask, inner, cv::Mat(), cv::Point(-1, -1), 1, cv::BORDER_REPLICATE);
  return cv::countNonZero(inner) > 0 ? inner : mask;
}

// Along the axis that split the classes, a pixel lying beyond the background's mean, away from
// the particles, is background however far it is (the darkest shadow between gravel grains);
// pulling such values back to the mean keeps the colour distance from folding over.
void clampBeyondBackground(cv::Mat& lab, const Axis& axis, const cv::Scalar& mean) {
  const bool above = axis.backgroundAbove;
  const double chroma = std::hypot(mean[1], mean[2]);
  for (int y = 0; y < lab.rows; ++y) {
    auto* p = lab.ptr<cv::Vec3f>(y);
    for (int x = 0; x < lab.cols; ++x) {
      if (axis.feature != kChroma) {
        float& v = p[x][axis.feature];
        const auto m = float(mean[axis.feature]);
        v = above ? std::min(v, m) : std::max(v, m);
        continue;
      }
      const double c = std::hypot(p[x][1], p[x][2]);
      if ((above ? c > chroma : c < chroma) && c > 1e-6)
        p[x][1] *= float(chroma / c), p[x][2] *= float(chroma / c);
    }
  }
}

// Colour distance (CIE76 Delta E) of every pixel from the background colour, after evening out
// the lighting; this catches particles of any hue (green candies are as bright as the paper,
// brown ones as unsaturated), which no single feature does.
cv::Mat backgroundDistance(const cv::Mat& lab, const Axis& axis, const cv::Mat& background) {
  const cv::Mat core = interior(background);
  cv::Mat flat = flattenShading(lab, core);
  const cv::Scalar mean = cv::mean(flat, core);
  clampBeyondBackground(flat, axis, mean);
  cv::Mat diff, distance;
  cv::subtract(flat, mean, diff);
  cv::multiply(diff, diff, diff);
  cv::transform(diff, distance, cv::Matx13f(1, 1, 1));
  cv::sqrt(distance, distance);
  // A 3x3 median removes sensor noise without moving edges or erasing thin spots.
  cv::medianBlur(distance, distance, 3);
  return distance;
}

}  // namespace

cv::Mat separateBackground(const cv::Mat& linear, double minArea, bool invert) {
  CV_Assert(linear.type() == CV_32FC3);
  const cv::Mat none = cv::Mat::zeros(linear.size(), CV_8UC1);
  const cv::Mat lab = linearToLab(linear);
  const auto f = features(lab);
  Axis axis = bestAxis(f);
  if (!axis.valid()) return none;
  const cv::Mat upper = f[std::size_t(axis.feature)] > axis.threshold;
  axis.backgroundAbove = upperIsBackground(upper, minArea);

  // The first guess came from one feature; re-estimate the background from the colour distance
  // once, then decide with the help of edges.
  cv::Mat distance = backgroundDistance(lab, axis, axis.backgroundAbove ? upper : cv::Mat(upper == 0));
  OtsuSplit split = otsu(distance);
  distance = backgroundDistance(lab, axis, distance <= split.threshold);
  split = otsu(distance);
  if (split.upperMean - split.lowerMean < kMinContrast) return none;
  const cv::Mat background = backgroundByEdges(distance, split);

  cv::Mat particles = invert ? background : cv::Mat(background == 0);
  removeSmallComponents(particles, minArea);
  fillSmallHoles(particles, minArea);
  return particles;
}

}  // namespace solidtex::detail
