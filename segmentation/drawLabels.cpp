#include "segmentation/drawLabels.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace solidtex {
namespace {

constexpr int kMinShortSide = 512;
constexpr int kMinParticleSide = 32;
constexpr int kMaxLongSide = 4096;
const cv::Scalar kInner(255, 230, 0), kBorder(255, 0, 255), kShadow(0, 0, 0), kText(255, 255, 255);

int medianParticleSide(const ExemplarStats& stats) {
  std::vector<int> sides;
  for (const Particle2D& p : stats.particles) sides.push_back(std::max(p.box.width, p.box.height));
  if (sides.empty()) return kMinParticleSide;
  std::nth_element(sides.begin(), sides.begin() + std::ptrdiff_t(sides.size() / 2), sides.end());
  return std::max(1, sides[sides.size() / 2]);
}

int scaleFor(const cv::Size& size, const ExemplarStats& stats) {
  const int shortSide = std::min(size.width, size.height), longSide = std::max(size.width, size.height);
  const int wanted = std::max((kMinShortSide + shortSide - 1) / shortSide,
                              (kMinParticleSide + medianParticleSide(stats) - 1) / medianParticleSide(stats));
  return std::clamp(std::min(wanted, kMaxLongSide / longSide), 1, 64);
}

// The label goes where the particle is thickest, which is inside it even for a crescent.
cv::Point labelAnchor(const Particle2D& p) {
  cv::Mat padded;
  cv::copyMakeBorder(p.mask, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::Mat dist;
  cv::distanceTransform(padded, dist, cv::DIST_L2, 3);
  cv::Point peak;
  cv::minMaxLoc(dist, nullptr, nullptr, nullptr, &peak);
  return p.box.tl() + peak - cv::Point(1, 1);
}

void drawOutline(cv::Mat& canvas, const Particle2D& p, int scale) {
  std::vector<cv::Point> scaled;
  scaled.reserve(p.contour.size());
  for (const cv::Point& q : p.contour) scaled.emplace_back(q * scale + cv::Point(scale / 2, scale / 2));
  const std::vector<std::vector<cv::Point>> poly{scaled};
  cv::polylines(canvas, poly, true, kShadow, 3, cv::LINE_AA);
  cv::polylines(canvas, poly, true, p.border ? kBorder : kInner, 1, cv::LINE_AA);
}

void drawId(cv::Mat& canvas, const Particle2D& p, int scale) {
  const std::string text = std::to_string(p.id);
  const double fontScale = 0.4;
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, fontScale, 1, &baseline);
  const cv::Point centre = labelAnchor(p) * scale + cv::Point(scale / 2, scale / 2);
  const cv::Point origin = centre + cv::Point(-size.width / 2, size.height / 2);
  cv::putText(canvas, text, origin, cv::FONT_HERSHEY_SIMPLEX, fontScale, kShadow, 3, cv::LINE_AA);
  cv::putText(canvas, text, origin, cv::FONT_HERSHEY_SIMPLEX, fontScale, p.border ? kBorder : kText, 1,
              cv::LINE_AA);
}

}  // namespace

cv::Mat drawLabels(const cv::Mat& photoSrgb, const ExemplarStats& stats) {
  CV_Assert(photoSrgb.type() == CV_32FC3);
  cv::Mat canvas;
  photoSrgb.convertTo(canvas, CV_8UC3, 255.0);
  const int scale = scaleFor(canvas.size(), stats);
  if (scale > 1) cv::resize(canvas, canvas, canvas.size() * scale, 0, 0, cv::INTER_NEAREST);
  for (const Particle2D& p : stats.particles) drawOutline(canvas, p, scale);
  for (const Particle2D& p : stats.particles) drawId(canvas, p, scale);
  return canvas;
}

}  // namespace solidtex
