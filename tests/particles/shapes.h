#pragma once
// Hand-made photo data for the particles tests, independent of the segmentation module.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <opencv2/imgproc.hpp>

#include "common/Random.h"
#include "particles/HullMesh.h"
#include "particles/VoxelShape.h"
#include "segmentation/ExemplarStats.h"

namespace solidtex::test {

inline constexpr double kPi = std::numbers::pi;

// The outer pixel contour of a filled polygon, as segmentation would find it.
inline std::vector<cv::Point> pixelContour(const std::vector<cv::Point>& outline) {
  cv::Rect box = cv::boundingRect(outline);
  cv::Mat mask = cv::Mat::zeros(box.height + 4, box.width + 4, CV_8U);
  std::vector<cv::Point> shifted;
  for (const cv::Point& p : outline) shifted.emplace_back(p.x - box.x + 2, p.y - box.y + 2);
  cv::fillPoly(mask, std::vector{shifted}, cv::Scalar(255));
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  auto largest = std::max_element(contours.begin(), contours.end(), [](const auto& a, const auto& b) {
    return cv::contourArea(a) < cv::contourArea(b);
  });
  for (cv::Point& p : *largest) p += cv::Point(box.x - 2, box.y - 2);
  return *largest;
}

// An ellipse of semi-axes rx and ry, its rx axis turned `angle` radians from x towards y.
inline std::vector<cv::Point> ellipseContour(double rx, double ry, cv::Point centre = {100, 100},
                                             double angle = 0) {
  std::vector<cv::Point> outline;
  const double c = std::cos(angle), s = std::sin(angle);
  for (int i = 0; i < 720; ++i) {
    const double t = 2 * kPi * i / 720, x = rx * std::cos(t), y = ry * std::sin(t);
    outline.emplace_back(int(std::lround(centre.x + c * x - s * y)),
                         int(std::lround(centre.y + s * x + c * y)));
  }
  return pixelContour(outline);
}

// A rounded, irregular stone outline of about `radius` pixels: a few random harmonics on a circle.
inline std::vector<cv::Point> gravelContour(Rng& rng, double radius) {
  double amplitude[5], phase[5];
  for (int h = 0; h < 5; ++h) {
    amplitude[h] = 0.12 * uniform01(rng) / (1 + h);
    phase[h] = 2 * kPi * uniform01(rng);
  }
  const double stretch = 0.6 + 0.4 * uniform01(rng);
  std::vector<cv::Point> outline;
  for (int i = 0; i < 360; ++i) {
    const double t = 2 * kPi * i / 360;
    double r = radius;
    for (int h = 0; h < 5; ++h) r += radius * amplitude[h] * std::cos((h + 2) * t + phase[h]);
    outline.emplace_back(int(std::lround(200 + r * std::cos(t))),
                         int(std::lround(200 + stretch * r * std::sin(t))));
  }
  return pixelContour(outline);
}

// Statistics of a photo whose particles have these contours; size pairs counted like segmentation does.
inline ExemplarStats statsOf(const std::vector<std::vector<cv::Point>>& contours) {
  ExemplarStats stats;
  std::map<std::pair<int, int>, int> pairs;
  for (std::size_t i = 0; i < contours.size(); ++i) {
    Particle2D p;
    p.id = int(i) + 1;
    p.contour = contours[i];
    p.box = cv::boundingRect(p.contour);
    p.area = cv::contourArea(p.contour);
    ++pairs[{p.box.width, p.box.height}];
    stats.particles.push_back(p);
  }
  for (const auto& [size, count] : pairs) stats.sizePairs.push_back({size.first, size.second, count});
  return stats;
}

// Statistics with each particle's mask filled from its contour, as segmentation leaves them.
inline ExemplarStats withMasks(ExemplarStats stats) {
  for (Particle2D& p : stats.particles) {
    p.mask = cv::Mat::zeros(p.box.size(), CV_8U);
    cv::fillPoly(p.mask, std::vector{p.contour}, cv::Scalar(255), cv::LINE_8, 0, -p.box.tl());
  }
  stats.imageWidth = stats.imageHeight = 4000;
  return stats;
}

inline ExemplarStats gravelStats(int count, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<std::vector<cv::Point>> contours;
  for (int i = 0; i < count; ++i) contours.push_back(gravelContour(rng, 10 + 25 * uniform01(rng)));
  return statsOf(contours);
}

// Every directed edge once and its reverse once: closed, manifold along edges, consistently oriented.
inline bool closedAndConsistent(const HullMesh& mesh) {
  std::set<std::pair<int, int>> edges;
  for (const auto& t : mesh.triangles)
    for (int c = 0; c < 3; ++c)
      if (!edges.insert({t[std::size_t(c)], t[std::size_t((c + 1) % 3)]}).second) return false;
  return std::all_of(edges.begin(), edges.end(), [&](const auto& e) {
    return edges.count({e.second, e.first}) == 1;
  });
}

// The 6-connected piece holding the first particle voxel, as a count.
inline std::size_t firstPieceSize(const VoxelShape& shape) {
  std::vector<std::uint8_t> seen(shape.inside.size(), 0);
  const auto first = std::find(shape.inside.begin(), shape.inside.end(), 1);
  if (first == shape.inside.end()) return 0;
  std::vector<std::size_t> queue{std::size_t(first - shape.inside.begin())};
  seen[queue[0]] = 1;
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const Voxel v = shape.dims.voxel(queue[q]);
    const int step[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    for (const auto& s : step) {
      const int i = v.x + s[0], j = v.y + s[1], k = v.z + s[2];
      if (!shape.dims.contains(i, j, k)) continue;
      const std::size_t n = shape.dims.index(i, j, k);
      if (shape.inside[n] && !seen[n]) {
        seen[n] = 1;
        queue.push_back(n);
      }
    }
  }
  return queue.size();
}

// Whether every face of the box holds a particle voxel.
inline bool tightInBox(const VoxelShape& shape) {
  int lo[3] = {shape.dims.x, shape.dims.y, shape.dims.z}, hi[3] = {-1, -1, -1};
  for (std::size_t i = 0; i < shape.inside.size(); ++i) {
    if (!shape.inside[i]) continue;
    const Voxel v = shape.dims.voxel(i);
    const int c[3] = {v.x, v.y, v.z};
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], c[a]);
      hi[a] = std::max(hi[a], c[a]);
    }
  }
  return lo[0] == 0 && lo[1] == 0 && lo[2] == 0 && hi[0] == shape.dims.x - 1 && hi[1] == shape.dims.y - 1 &&
         hi[2] == shape.dims.z - 1;
}

}  // namespace solidtex::test
