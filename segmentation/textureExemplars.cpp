#include "segmentation/textureExemplars.h"

#include <opencv2/imgproc.hpp>

#include "segmentation/detail/exemplarWindow.h"
#include "segmentation/particleShading.h"

namespace solidtex {
namespace {

cv::Mat disc(int radius) {
  return cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * radius + 1, 2 * radius + 1});
}

}  // namespace

cv::Mat matrixExemplar(const ExemplarStats& stats, const TextureExemplarOptions& options) {
  cv::Mat known;
  cv::erode(stats.backgroundMask, known, disc(options.rim), {-1, -1}, 1, cv::BORDER_REPLICATE);
  const cv::Mat linear =
      stats.backgroundResidual +
      cv::Scalar(stats.backgroundColor[0], stats.backgroundColor[1], stats.backgroundColor[2]);
  return segmentation::detail::exemplarWindow(linear, known, options.maxSide, options.minShare);
}

cv::Mat particleExemplar(const ExemplarStats& stats, const TextureExemplarOptions& options) {
  const cv::Size size = stats.backgroundMask.size();
  cv::Mat linear(size, CV_32FC3, cv::Scalar::all(0.5)), known = cv::Mat::zeros(size, CV_8U), inside;
  for (const Particle2D& particle : stats.particles) {
    // Each particle's own outline is left out, so touching particles keep theirs apart.
    cv::erode(particle.mask, inside, disc(options.rim), {-1, -1}, 1, cv::BORDER_CONSTANT, 0);
    cv::Mat(splitResidual(particle).grain + cv::Scalar::all(0.5)).copyTo(linear(particle.box), inside);
    known(particle.box).setTo(255, inside);
  }
  return segmentation::detail::exemplarWindow(linear, known, options.maxSide, options.minShare);
}

}  // namespace solidtex
