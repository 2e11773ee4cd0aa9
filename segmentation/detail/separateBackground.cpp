#include "segmentation/detail/separateBackground.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "segmentation/detail/chooseBackground.h"
#include "segmentation/detail/color.h"
#include "segmentation/detail/edgeDecision.h"
#include "segmentation/detail/flattenShading.h"
#include "segmentation/detail/morphology.h"
#include "segmentation/detail/otsu.h"

namespace solidtex::segmentation::detail {
namespace {

constexpr double kMinSpread = 1.0;     // Lab units: a feature flatter than this carries no classes
constexpr double kMinContrast = 5.0;   // Delta E between the class means: below it, no visible classes
constexpr int kChroma = 3;             // feature index after L, a, b
constexpr double kClearlyMore = 1.25;  // another reading's solid share over the first's, to win
constexpr double kMaxGapShare = 0.35;  // the gaps of a pile are the smaller, darker class
constexpr double kGrainSigma = 1.0;    // pixels: the window of the matrix's grain
constexpr float kGrainWeight = 3.0f;   // Delta E per unit of L* spread smoother than the matrix

// The feature that separates the classes best, and on which side of it the background lies.
struct Axis {
  int feature = -1;  // 0..2: L, a, b; kChroma: chroma
  float threshold = 0;
  bool backgroundAbove = false;
  bool twoSided = false;  // particles lie on both sides of the background along the feature
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
// `above`, when given, receives the pixels beyond the background's mean along the axis.
cv::Mat backgroundDistance(const cv::Mat& lab, const Axis& axis, const cv::Mat& background,
                           cv::Mat* above = nullptr) {
  const cv::Mat core = interior(background);
  cv::Mat flat = flattenShading(lab, core);
  const cv::Scalar mean = cv::mean(flat, core);
  if (above) {
    cv::extractChannel(flat, *above, axis.feature);
    *above = *above > mean[axis.feature];
  }
  if (!axis.twoSided) clampBeyondBackground(flat, axis, mean);
  cv::Mat diff, distance;
  cv::subtract(flat, mean, diff);
  cv::multiply(diff, diff, diff);
  cv::transform(diff, distance, cv::Matx13f(1, 1, 1));
  cv::sqrt(distance, distance);
  // A 3x3 median removes sensor noise without moving straight edges or erasing thin spots; it
  // rounds corners, which analyzeExemplar's outlines put back (restoreCorners).
  cv::medianBlur(distance, distance, 3);
  return distance;
}

// Background (255) by one threshold on the colour distance; empty when there is no clear contrast.
cv::Mat oneSidedBackground(const cv::Mat& lab, const Axis& axis, const cv::Mat& firstGuess) {
  // The first guess came from one feature; re-estimate the background from the colour distance
  // once, then decide with the help of edges.
  cv::Mat distance = backgroundDistance(lab, axis, firstGuess);
  OtsuSplit split = otsu(distance);
  distance = backgroundDistance(lab, axis, distance <= split.threshold);
  split = otsu(distance);
  if (split.upperMean - split.lowerMean < kMinContrast) return {};
  return backgroundByEdges(distance, split);
}

// The spread of lightness within a few pixels of each pixel: the grain of sand or mortar.
cv::Mat localSpread(const cv::Mat& lab) {
  cv::Mat lightness, mean, meanSq, spread;
  cv::extractChannel(lab, lightness, 0);
  cv::GaussianBlur(lightness, mean, {0, 0}, kGrainSigma);
  cv::GaussianBlur(lightness.mul(lightness), meanSq, {0, 0}, kGrainSigma);
  cv::sqrt(cv::max(meanSq - mean.mul(mean), 0), spread);
  return spread;
}

// A matrix of sand or mortar is grainier than the smooth particles set in it, even where a
// particle's shaded side takes the matrix's colour: being smoother than the matrix's typical grain
// adds to the distance, kGrainWeight Delta E per unit of lightness spread.
void addSmoothness(cv::Mat& distance, const cv::Mat& grain, const cv::Mat& background) {
  std::vector<float> values;
  for (int y = 0; y < grain.rows; ++y)
    for (int x = 0; x < grain.cols; ++x)
      if (background.at<uchar>(y, x)) values.push_back(grain.at<float>(y, x));
  if (values.empty()) return;
  const auto mid = values.begin() + std::ptrdiff_t(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  cv::Mat smoother = cv::max(float(*mid) - grain, 0) * kGrainWeight;
  cv::sqrt(distance.mul(distance) + smoother.mul(smoother), distance);
}

// The background of particles lighter and darker than it: on each side of the background's
// lightness the colour distance has a threshold of its own, since one tone lies further from the
// matrix than the other. `middle` is the first guess.
cv::Mat twoSidedBackground(const cv::Mat& lab, const cv::Mat& middle) {
  const Axis lightness{0, 0, false, true};
  const cv::Mat grain = localSpread(lab);
  cv::Mat background = middle, distance, above, seeds;
  float lowest = 0;
  for (int pass = 0; pass < 2; ++pass) {
    distance = backgroundDistance(lab, lightness, background, &above);
    addSmoothness(distance, grain, background);
    const OtsuSplit lighter = otsu(distance, above), darker = otsu(distance, ~above);
    const auto seedsOf = [&](const OtsuSplit& split, const cv::Mat& side) {
      if (split.upperMean - split.lowerMean < kMinContrast)
        return cv::Mat(cv::Mat::zeros(side.size(), CV_8U));
      return cv::Mat(side & (distance > split.threshold));
    };
    seeds = seedsOf(lighter, above) | seedsOf(darker, ~above);
    background = ~seeds;
    lowest = std::min(lighter.threshold, darker.threshold);
  }
  if (cv::countNonZero(seeds) == 0) return {};
  return backgroundByEdges(distance, seeds, lowest);
}

// True when most of `mask` is one 8-connected piece: the gaps of a pile join up around its
// particles, while dark particles scattered on a light ground are as many pieces as particles.
bool isNetwork(const cv::Mat& mask) {
  cv::Mat labels, pieces, centroids;
  const int count = cv::connectedComponentsWithStats(mask, labels, pieces, centroids, 8, CV_32S);
  int largest = 0;
  for (int p = 1; p < count; ++p) largest = std::max(largest, pieces.at<int>(p, cv::CC_STAT_AREA));
  return largest >= 0.5 * cv::countNonZero(mask);
}

cv::Mat particlesFrom(const cv::Mat& background, double minArea, bool invert) {
  cv::Mat particles = invert ? background : cv::Mat(background == 0);
  removeSmallComponents(particles, minArea);
  fillSmallHoles(particles, minArea);
  return particles;
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
  const cv::Mat background =
      oneSidedBackground(lab, axis, axis.backgroundAbove ? upper : cv::Mat(upper == 0));
  cv::Mat particles = background.empty() ? none : particlesFrom(background, minArea, invert);

  // Two other readings, for photos the clearest feature misreads:
  // - particles of two tones, one lighter and one darker than the matrix between them (pebbles in
  //   mortar), where one threshold finds one tone only;
  // - a pile of particles of many colours (beach shingle), where the clearest feature splits the
  //   particles by colour and only the dark gaps between them, joined up, are background.
  // Another reading wins when its particles cover clearly more of the photo in compact bodies
  // (a quarter more: the rosettes of a leopard's coat read either way, and the first reading
  // reads them as they look).
  std::vector<cv::Mat> others;
  if (const cv::Mat middle = middleLightnessClass(f[0], minArea); !middle.empty())
    others.push_back(twoSidedBackground(lab, middle));
  if (axis.feature != 0 || axis.backgroundAbove) {
    const Axis darkGaps{0, otsu(f[0]).threshold, false};
    const cv::Mat gaps = f[0] <= darkGaps.threshold;
    if (cv::countNonZero(gaps) <= kMaxGapShare * double(gaps.total()))
      if (cv::Mat background = oneSidedBackground(lab, darkGaps, gaps);
          !background.empty() && isNetwork(background))
        others.push_back(background);
  }
  double best = kClearlyMore * solidShare(invert ? ~particles : particles, minArea);
  cv::Mat chosen = particles;
  for (const cv::Mat& other : others) {
    if (other.empty()) continue;
    cv::Mat alternative = particlesFrom(other, minArea, invert);
    const double share = solidShare(invert ? ~alternative : alternative, minArea);
    if (share > best) best = share, chosen = alternative;
  }
  return chosen;
}

}  // namespace solidtex::segmentation::detail
