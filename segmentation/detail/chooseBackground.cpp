#include "segmentation/detail/chooseBackground.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "segmentation/detail/otsu.h"
#include "segmentation/detail/shape.h"
#include "segmentation/detail/splitParticles.h"

namespace solidtex::segmentation::detail {
namespace {

constexpr double kDecisionPixels = 512.0 * 512.0;
constexpr double kMinToneShare = 0.05;   // each tone at least this share of the photo
constexpr double kClassSmoothing = 1.5;  // pixels: Gaussian sigma before the three classes

// Pixels of one body times its solidity.
double solidPixels(const cv::Mat& labels, int label, const cv::Rect& box, double minArea) {
  const cv::Mat body = labels(box) == label;
  const double area = cv::countNonZero(body);
  if (area < minArea) return 0;
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(body, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  std::vector<cv::Point> points;
  for (const auto& c : contours) points.insert(points.end(), c.begin(), c.end());
  return area * std::min(1.0, area / hullPixelArea(hullOf(points)));
}

// True when the pixels 3 to 5 pixels outside `region` lie more in `near` than in `far`. Nearer
// pixels are left out: the blurred edge between two other classes passes through the middle one.
bool mostlyBeside(const cv::Mat& region, const cv::Mat& near, const cv::Mat& far) {
  cv::Mat inner, ring;
  cv::dilate(region, inner, cv::getStructuringElement(cv::MORPH_ELLIPSE, {5, 5}));
  cv::dilate(region, ring, cv::getStructuringElement(cv::MORPH_ELLIPSE, {11, 11}));
  ring &= ~inner;
  return cv::countNonZero(ring & near) > cv::countNonZero(ring & far);
}

}  // namespace

double compactness(const cv::Mat& classMask, double minArea) {
  const double total = cv::countNonZero(classMask);
  if (total == 0) return 0;
  const cv::Mat labels = labelParticles(classMask, true);
  const std::vector<cv::Rect> boxes = labelBoxes(labels);
  double solid = 0;
  for (int label = 1; label < int(boxes.size()); ++label)
    if (!boxes[std::size_t(label)].empty() && !touchesBorder(boxes[std::size_t(label)], labels.size()))
      solid += solidPixels(labels, label, boxes[std::size_t(label)], minArea);
  return solid / total;
}

namespace {

// Judgements on the whole photo are made on a copy of about a quarter megapixel: it shows the same
// bodies, and cutting the classes of a large photo into bodies would cost seconds.
int decisionFactor(const cv::Mat& image) {
  return std::max(1, int(std::ceil(std::sqrt(double(image.total()) / kDecisionPixels))));
}

cv::Mat forDecision(const cv::Mat& image, int factor) {
  if (factor <= 1) return image;
  cv::Mat small;
  cv::resize(image, small, cv::Size(image.cols / factor, image.rows / factor), 0, 0, cv::INTER_AREA);
  return image.type() == CV_8UC1 ? cv::Mat(small >= 128) : small;
}

}  // namespace

bool upperIsBackground(const cv::Mat& upper, double minArea) {
  const int factor = decisionFactor(upper);
  const cv::Mat small = forDecision(upper, factor);
  const double smallMinArea = minArea / double(factor * factor);
  return compactness(small, smallMinArea) < compactness(small == 0, smallMinArea);
}

double solidShare(const cv::Mat& particles, double minArea) {
  const int factor = decisionFactor(particles);
  const cv::Mat small = forDecision(particles, factor);
  return compactness(small, minArea / double(factor * factor)) * cv::countNonZero(small) /
         double(small.total());
}

cv::Mat middleLightnessClass(const cv::Mat& lightness, double minArea) {
  CV_Assert(lightness.type() == CV_32FC1);
  cv::Mat smooth;
  cv::GaussianBlur(lightness, smooth, {0, 0}, kClassSmoothing, kClassSmoothing, cv::BORDER_REFLECT);
  const OtsuThreeClasses split = otsuThreeClasses(smooth);
  const cv::Mat low = smooth <= split.lower, high = smooth > split.upper;
  const double fewest = std::min(cv::countNonZero(low), cv::countNonZero(high));
  if (fewest < kMinToneShare * double(lightness.total())) return {};
  const cv::Mat middle = ~(low | high);
  const int factor = decisionFactor(middle);
  const double smallMinArea = minArea / double(factor * factor);
  const auto compact = [&](const cv::Mat& mask) {
    return compactness(forDecision(mask, factor), smallMinArea);
  };
  const double middleCompactness = compact(middle);
  if (middleCompactness >= compact(low) || middleCompactness >= compact(high)) return {};
  // The matrix lies between the tones: each tone's outline runs mostly along the middle class
  // rather than along the other tone (orange and blue discs on a dark ground are one tone each
  // side of blue, but the orange ones lie on the ground).
  if (!mostlyBeside(low, middle, high) || !mostlyBeside(high, middle, low)) return {};
  return middle;
}

}  // namespace solidtex::segmentation::detail
