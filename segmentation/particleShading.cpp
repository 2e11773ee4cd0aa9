#include "segmentation/particleShading.h"

#include <vector>

#include <opencv2/imgproc.hpp>

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

}  // namespace solidtex
