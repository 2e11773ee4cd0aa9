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
constexpr double kWander = 0.9;   // quantile of the background's distances whose rise over the median
                                  // is its wander
// Lowest share of the way up: the curvature correction holds for particles wider than the blur,
// and must not take a speck's level down to the background's.
constexpr double kLowestShare = 0.25;

// Labels grown `reach` pixels into the unlabelled ones around them (3x3 steps; where two meet, the
// larger label takes the pixel: deterministic). Dilated as doubles, which OpenCV's morphology
// takes and which hold every label exactly.
cv::Mat grownLabels(const cv::Mat& labels, int reach) {
  cv::Mat grown, dilated;
  labels.convertTo(grown, CV_64F);
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
  selected.convertTo(labels, CV_64F);
  cv::dilate(labels, largestAround, cv::Mat());
  return (labels > 0) & (largestAround <= labels);
}

// The share of the way from the background's distance to a particle's plateau at which its outline
// lies, for a disc of `radius` blurred by `sigma` in all (the photo's blur and the smoothing). Half
// way for a straight edge; a convex outline's half-way level lies sigma^2 / (2 radius) inside it,
// which at the edge's slope (1 / (sigma sqrt(2 pi)) of the step per pixel) is that much lower a
// level. A small disc's own plateau, its blurred peak, is already lower than the full step by
// about exp(-radius^2 / (2 sigma^2)), which lowers its half-way level by half as much: that is
// taken off the correction.
double halfWayShare(double radius, double sigma) {
  const double curvature = sigma / (2 * std::sqrt(2 * std::numbers::pi) * radius);
  const double lowPeak = 0.5 * std::exp(-radius * radius / (2 * sigma * sigma));
  return std::max(kLowestShare, 0.5 - std::max(0.0, curvature - lowPeak));
}

float quantile(std::vector<float>& values, double share) {
  const auto at = values.begin() + std::ptrdiff_t(share * double(values.size() - 1));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

// Each particle's level (indexed by label) and whether the background is plain enough for it.
struct EdgeLevels {
  std::vector<float> level;
  bool plainBackground = false;
};

// The background's level is its median away from every edge (`reach` + 1 pixels out); a particle's
// plateau is its kPlateau quantile.
EdgeLevels edgeLevels(const cv::Mat& smooth, const cv::Mat& particles, const cv::Mat& labels,
                      const cv::Mat& pieces, double blur, int reach, double maxBackgroundSpread) {
  const int count = pieces.rows;
  cv::Mat nearParticles;
  cv::dilate(particles, nearParticles, cv::Mat(), {-1, -1}, reach + 1);
  std::vector<float> background;
  std::vector<std::vector<float>> inside(static_cast<std::size_t>(count));
  for (int y = 0; y < smooth.rows; ++y)
    for (int x = 0; x < smooth.cols; ++x) {
      const int label = labels.at<int>(y, x);
      if (label > 0)
        inside[std::size_t(label)].push_back(smooth.at<float>(y, x));
      else if (!nearParticles.at<uchar>(y, x))
        background.push_back(smooth.at<float>(y, x));
    }
  EdgeLevels levels{std::vector<float>(std::size_t(count), 0)};
  if (background.empty() || count < 2) return levels;
  const float low = quantile(background, 0.5), wander = quantile(background, kWander) - low;
  std::vector<float> contrast;
  for (int label = 1; label < count; ++label) {
    const double radius = std::sqrt(pieces.at<int>(label, cv::CC_STAT_AREA) / std::numbers::pi);
    const float high = quantile(inside[std::size_t(label)], kPlateau);
    levels.level[std::size_t(label)] =
        low + float(halfWayShare(radius, std::sqrt(2.0) * blur)) * (high - low);
    contrast.push_back(high - low);
  }
  levels.plainBackground = !(wander > maxBackgroundSpread * quantile(contrast, 0.5));
  return levels;
}

}  // namespace

cv::Mat halfMaximumOutlines(const cv::Mat& lab, const cv::Mat& particles, double blur,
                            double maxBackgroundSpread) {
  CV_Assert(lab.type() == CV_32FC3 && particles.type() == CV_8UC1 && blur > 0);
  cv::Mat smoothLab;
  cv::GaussianBlur(lab, smoothLab, {0, 0}, blur, blur, cv::BORDER_REFLECT);
  const cv::Mat smooth = distanceFromBackground(smoothLab, particles == 0);
  const int reach = int(std::ceil(2 * blur));
  cv::Mat labels, pieces, centroids;
  cv::connectedComponentsWithStats(particles, labels, pieces, centroids, 8, CV_32S);
  const EdgeLevels levels = edgeLevels(smooth, particles, labels, pieces, blur, reach, maxBackgroundSpread);
  if (!levels.plainBackground) return {};

  const cv::Mat grown = grownLabels(labels, reach);
  cv::Mat selected = cv::Mat::zeros(particles.size(), CV_32S);
  for (int y = 0; y < smooth.rows; ++y)
    for (int x = 0; x < smooth.cols; ++x)
      if (const int label = grown.at<int>(y, x);
          label > 0 && smooth.at<float>(y, x) >= levels.level[std::size_t(label)])
        selected.at<int>(y, x) = label;
  return keptApart(selected);
}

}  // namespace solidtex::segmentation::detail
