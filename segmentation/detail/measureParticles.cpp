#include "segmentation/detail/measureParticles.h"

#include <algorithm>
#include <tuple>

#include <opencv2/imgproc.hpp>

#include "segmentation/detail/shape.h"

namespace solidtex::segmentation::detail {
namespace {

std::vector<cv::Point> largestOuterContour(const cv::Mat& region) {
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(region, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  if (contours.empty()) return {};
  return *std::max_element(contours.begin(), contours.end(), [](const auto& a, const auto& b) {
    return cv::contourArea(a) < cv::contourArea(b);
  });
}

void measureColor(Particle2D& p, const cv::Mat& linear) {
  const cv::Mat pixels = linear(p.box);
  const cv::Scalar mean = cv::mean(pixels, p.mask);
  p.color = cv::Vec3f(float(mean[0]), float(mean[1]), float(mean[2]));
  p.residual = cv::Mat::zeros(p.box.size(), CV_32FC3);
  cv::subtract(pixels, cv::Scalar(mean[0], mean[1], mean[2]), p.residual, p.mask);
}

bool measureOne(int label, const cv::Rect& box, const cv::Mat& labels, const cv::Mat& linear, Particle2D& p) {
  p.mask = labels(box) == label;
  std::vector<cv::Point> contour = largestOuterContour(p.mask);
  if (contour.empty()) return false;
  p.box = box;
  for (cv::Point& q : contour) q += box.tl();
  p.contour = std::move(contour);
  p.area = cv::countNonZero(p.mask);
  p.border = touchesBorder(box, labels.size());
  measureColor(p, linear);
  return true;
}

void sortAndNumber(std::vector<Particle2D>& particles) {
  std::sort(particles.begin(), particles.end(), [](const Particle2D& a, const Particle2D& b) {
    return std::make_tuple(a.box.y, a.box.x, a.box.height, a.box.width, a.area) <
           std::make_tuple(b.box.y, b.box.x, b.box.height, b.box.width, b.area);
  });
  for (std::size_t i = 0; i < particles.size(); ++i) particles[i].id = int(i) + 1;
}

}  // namespace

std::vector<Particle2D> measureParticles(const cv::Mat& labels, const cv::Mat& linear, double minArea) {
  CV_Assert(labels.type() == CV_32SC1 && linear.type() == CV_32FC3 && labels.size() == linear.size());
  const std::vector<cv::Rect> boxes = labelBoxes(labels);
  std::vector<Particle2D> particles;
  for (int label = 1; label < int(boxes.size()); ++label) {
    if (boxes[std::size_t(label)].empty()) continue;
    Particle2D p;
    if (measureOne(label, boxes[std::size_t(label)], labels, linear, p) && p.area >= minArea && p.area > 0)
      particles.push_back(std::move(p));
  }
  sortAndNumber(particles);
  return particles;
}

void measureBackground(ExemplarStats& stats, const cv::Mat& linear) {
  stats.backgroundMask = cv::Mat(linear.size(), CV_8UC1, cv::Scalar(255));
  for (const Particle2D& p : stats.particles) stats.backgroundMask(p.box).setTo(0, p.mask);
  const int backgroundPixels = cv::countNonZero(stats.backgroundMask);
  const cv::Scalar mean = backgroundPixels > 0 ? cv::mean(linear, stats.backgroundMask) : cv::mean(linear);
  stats.backgroundColor = cv::Vec3f(float(mean[0]), float(mean[1]), float(mean[2]));
  stats.backgroundResidual = cv::Mat::zeros(linear.size(), CV_32FC3);
  cv::subtract(linear, cv::Scalar(mean[0], mean[1], mean[2]), stats.backgroundResidual, stats.backgroundMask);
  stats.areaFraction = 1.0 - double(backgroundPixels) / double(linear.total());
}

}  // namespace solidtex::segmentation::detail
