#include "segmentation/particleShading.h"

#include <cmath>
#include <limits>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "segmentation/detail/color.h"

namespace solidtex {

ResidualScales splitResidual(const Particle2D& particle, double sigma) {
  cv::Mat weight, blurredWeight, blurred, weight3;
  particle.mask.convertTo(weight, CV_32F, 1.0 / 255);
  cv::GaussianBlur(particle.residual, blurred, {0, 0}, sigma, sigma, cv::BORDER_CONSTANT);
  cv::GaussianBlur(weight, blurredWeight, {0, 0}, sigma, sigma, cv::BORDER_CONSTANT);
  cv::merge(std::vector<cv::Mat>(3, cv::max(blurredWeight, 1e-6f)), weight3);
  ResidualScales scales;
  scales.shading = cv::Mat::zeros(particle.residual.size(), CV_32FC3);
  cv::divide(blurred, weight3, blurred);
  blurred.copyTo(scales.shading, particle.mask);
  scales.grain = particle.residual - scales.shading;
  return scales;
}

double grainContrast(const Particle2D& particle) {
  constexpr int kLeastPixels = 9;
  cv::Mat interior;
  for (const int width : {5, 3}) {
    cv::erode(particle.mask, interior, cv::getStructuringElement(cv::MORPH_ELLIPSE, {width, width}), {-1, -1},
              1, cv::BORDER_CONSTANT, 0);
    if (cv::countNonZero(interior) >= kLeastPixels) break;
  }
  if (cv::countNonZero(interior) < kLeastPixels) return std::numeric_limits<double>::quiet_NaN();
  const ResidualScales scales = splitResidual(particle);
  const cv::Scalar mean(particle.color[0], particle.color[1], particle.color[2]);
  // The grain in L*: the photo's lightness less the shading's, both about the particle's colour.
  cv::Mat photo, shading, difference;
  cv::add(particle.residual, mean, photo);
  cv::add(scales.shading, mean, shading);
  cv::extractChannel(segmentation::detail::linearToLab(cv::max(photo, 0.0f)), photo, 0);
  cv::extractChannel(segmentation::detail::linearToLab(cv::max(shading, 0.0f)), shading, 0);
  cv::subtract(photo, shading, difference);
  const double squares = cv::norm(difference, cv::NORM_L2SQR, interior);
  return std::sqrt(squares / cv::countNonZero(interior));
}

}  // namespace solidtex
