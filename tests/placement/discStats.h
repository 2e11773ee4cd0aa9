#pragma once
// The statistics of a photo of discs, as segmentation would report them, for the placement tests.
#include <algorithm>
#include <map>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "particles/ParticleFactory.h"
#include "segmentation/ExemplarStats.h"

namespace solidtex::test {

// The statistics segmentation would report for a photo of discs: radius -> how many.
inline ExemplarStats discStats(const std::map<int, int>& discs, double areaFraction) {
  ExemplarStats stats;
  stats.name = "discs";
  stats.imageWidth = stats.imageHeight = 200;
  std::map<std::pair<int, int>, int> pairs;
  for (const auto& [radius, count] : discs)
    for (int i = 0; i < count; ++i) {
      Particle2D p;
      p.id = int(stats.particles.size()) + 1;
      cv::ellipse2Poly(cv::Point(100, 100), cv::Size(radius, radius), 0, 0, 360, 5, p.contour);
      p.area = cv::contourArea(p.contour);
      p.box = cv::boundingRect(p.contour);
      p.color = cv::Vec3f(0.5f, 0.4f, 0.3f);
      p.mask = cv::Mat(p.box.size(), CV_8U, cv::Scalar(255));
      p.residual = cv::Mat::zeros(p.box.size(), CV_32FC3);
      ++pairs[{p.box.width, p.box.height}];
      stats.particles.push_back(p);
    }
  const auto [smallest, largest] =
      std::minmax_element(stats.particles.begin(), stats.particles.end(),
                          [](const auto& a, const auto& b) { return a.area < b.area; });
  for (int i = 0; i <= 10; ++i)
    stats.histogram.edges[std::size_t(i)] = smallest->area + (largest->area - smallest->area) * i / 10;
  for (const Particle2D& p : stats.particles)
    ++stats.histogram.counts[std::size_t(stats.histogram.binOf(p.area))];
  for (int i = 0; i < 10; ++i)
    stats.histogram.ratios[std::size_t(i)] =
        double(stats.histogram.counts[std::size_t(i)]) / double(stats.particles.size());
  for (const auto& [size, count] : pairs) stats.sizePairs.push_back({size.first, size.second, count});
  stats.areaFraction = areaFraction;
  return stats;
}

inline const std::map<int, int> kDiscs{{3, 14}, {4, 10}, {5, 7}, {6, 5}, {8, 3}, {10, 1}};

inline ParticleOptions fewShapes() {
  ParticleOptions options;
  options.shapes = 6;
  return options;
}

}  // namespace solidtex::test
