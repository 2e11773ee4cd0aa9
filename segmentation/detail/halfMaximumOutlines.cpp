#include "segmentation/detail/halfMaximumOutlines.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "segmentation/detail/outlineBlur.h"

namespace solidtex::segmentation::detail {
namespace {

constexpr double kPlateau = 0.9;  // quantile of a particle's smoothed distances taken as its plateau

// Labels grown `reach` pixels into the unlabelled ones around them (3x3 steps; where two meet, the
// larger label takes the pixel: deterministic). Dilated as floats, which OpenCV's morphology
// takes and which hold labels exactly up to 2^24.
cv::Mat grownLabels(const cv::Mat& labels, int reach) {
  cv::Mat grown, dilated;
  labels.convertTo(grown, CV_32F);
  for (int step = 0; step < reach; ++step) {
    cv::dilate(grown, dilated, cv::Mat());
    dilated.copyTo(grown, grown == 0);
  }
  grown.convertTo(grown, CV_32S);
  return grown;
}

// The pixels of the labels, as a CV_8U mask, less those next to a pixel of a larger label: particles
// that were apart stay apart, however far each grew (8-connected: not even diagonally joined).
cv::Mat keptApart(const cv::Mat& selected) {
  cv::Mat labels, largestAround;
  selected.convertTo(labels, CV_32F);
  cv::dilate(labels, largestAround, cv::Mat());
  return (labels > 0) & (largestAround <= labels);
}

// The share of the way from the background's distance to a particle's plateau at which its outline
// lies, for a disc of `radius` blurred by `sigma` in all (the photo's blur and the smoothing). Half
// way for a straight edge; a convex outline's half-way level lies sigma^2 / (2 radius) inside it,
// which at the edge's slope (1 / (sigma sqrt(2 pi)) of the step per pixel) is that much lower a
// level. A small disc's own plateau, its blurred peak, is already lower than the full step by
// about exp(-radius^2 / (2 sigma^2)): half of that lowering is taken off the correction.
double halfWayShare(double radius, double sigma) {
  const double curvature = sigma / (2 * std::sqrt(2 * std::numbers::pi) * radius);
  const double lowPeak = 0.5 * std::exp(-radius * radius / (2 * sigma * sigma));
  return 0.5 - std::max(0.0, curvature - lowPeak);
}

float quantile(std::vector<float>& values, double share) {
  const auto at = values.begin() + std::ptrdiff_t(share * double(values.size() - 1));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

}  // namespace

cv::Mat halfMaximumOutlines(const cv::Mat& lab, const cv::Mat& particles, double blur,
                            double maxBackgroundSpread) {
  CV_Assert(lab.type() == CV_32FC3 && particles.type() == CV_8UC1 && blur > 0);
  cv::Mat smoothLab, labels, pieces, centroids;
  cv::GaussianBlur(lab, smoothLab, {0, 0}, blur, blur, cv::BORDER_REFLECT);
  const cv::Mat smooth = distanceFromBackground(smoothLab, particles == 0);
  const int count = cv::connectedComponentsWithStats(particles, labels, pieces, centroids, 8, CV_32S);
  const int reach = int(std::ceil(2 * blur));

  // The background's level away from every edge, and each particle's plateau.
  cv::Mat farBackground;
  cv::dilate(particles, farBackground, cv::Mat(), {-1, -1}, reach + 1);
  std::vector<float> background;
  std::vector<std::vector<float>> inside(static_cast<std::size_t>(count));
  for (int y = 0; y < smooth.rows; ++y)
    for (int x = 0; x < smooth.cols; ++x) {
      const int label = labels.at<int>(y, x);
      if (label > 0)
        inside[std::size_t(label)].push_back(smooth.at<float>(y, x));
      else if (!farBackground.at<uchar>(y, x))
        background.push_back(smooth.at<float>(y, x));
    }
  if (background.empty()) return {};
  const float low = quantile(background, 0.5), wander = quantile(background, kPlateau) - low;

  std::vector<float> level(std::size_t(count), 0), contrast;
  for (int label = 1; label < count; ++label) {
    const double radius = std::sqrt(pieces.at<int>(label, cv::CC_STAT_AREA) / std::numbers::pi);
    const float high = quantile(inside[std::size_t(label)], kPlateau);
    level[std::size_t(label)] = low + float(halfWayShare(radius, std::sqrt(2.0) * blur)) * (high - low);
    contrast.push_back(high - low);
  }
  if (contrast.empty()) return {};
  const float typicalContrast = quantile(contrast, 0.5);
  if (!(wander <= maxBackgroundSpread * typicalContrast)) return {};

  const cv::Mat grown = grownLabels(labels, reach);
  cv::Mat selected = cv::Mat::zeros(particles.size(), CV_32S);
  for (int y = 0; y < smooth.rows; ++y)
    for (int x = 0; x < smooth.cols; ++x)
      if (const int label = grown.at<int>(y, x);
          label > 0 && smooth.at<float>(y, x) >= level[std::size_t(label)])
        selected.at<int>(y, x) = label;
  return keptApart(selected);
}

}  // namespace solidtex::segmentation::detail
