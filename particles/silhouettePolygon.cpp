// Silhouette polygons: contour simplification, normalisation and repair (no CGAL here).
#include "particles/visualHull.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include <opencv2/imgproc.hpp>

namespace solidtex {
namespace {

using Polygon = std::vector<Eigen::Vector2d>;

// Polygon features narrower than this (in the unit square) are cut away, so that rounding the prism
// corners (by at most 2^-17) cannot make a prism's surface touch itself.
constexpr double kClearance = 1.0 / 1024;

double signedArea(const Polygon& poly) {
  double twice = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d& a = poly[i];
    const Eigen::Vector2d& b = poly[(i + 1) % poly.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return twice / 2;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

Eigen::Vector2d closestOnSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                 const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  return length2 > 0 ? Eigen::Vector2d(a + std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) * ab) : a;
}

double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (p - closestOnSegment(p, a, b)).norm();
}

struct Meeting {
  Eigen::Vector2d point;  // halfway between the closest points
  double distance;
};

Meeting nearestMeeting(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                       const Eigen::Vector2d& d) {
  const double ca = cross(c, d, a), cb = cross(c, d, b);
  if (ca * cb < 0 && cross(a, b, c) * cross(a, b, d) < 0) return {a + ca / (ca - cb) * (b - a), 0};
  Meeting best{a, std::numeric_limits<double>::infinity()};
  for (const auto& [p, q] :
       {std::pair{a, closestOnSegment(a, c, d)}, std::pair{b, closestOnSegment(b, c, d)},
        std::pair{c, closestOnSegment(c, a, b)}, std::pair{d, closestOnSegment(d, a, b)}})
    if ((p - q).norm() < best.distance) best = {(p + q) / 2, (p - q).norm()};
  return best;
}

// Drops vertices that are repeated, nearly collinear with their neighbours or the tip of a spike
// narrower than the clearance.
void dropThinVertices(Polygon& poly) {
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < poly.size() && poly.size() >= 3; ++i) {
      const std::size_t n = poly.size();
      const Eigen::Vector2d &prev = poly[(i + n - 1) % n], &v = poly[i], &next = poly[(i + 1) % n];
      if (distanceToSegment(v, prev, next) < kClearance || distanceToSegment(next, prev, v) < kClearance ||
          distanceToSegment(prev, v, next) < kClearance) {
        poly.erase(poly.begin() + std::ptrdiff_t(i));
        changed = true;
      }
    }
  }
}

struct Pinch {
  std::size_t i, j;  // non-adjacent edges, i < j
  Eigen::Vector2d point;
};

// The first pair of non-adjacent edges closer than the clearance (crossing ones included).
std::optional<Pinch> firstPinch(const Polygon& poly) {
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i + 2 < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      const Meeting m = nearestMeeting(poly[i], poly[i + 1], poly[j], poly[(j + 1) % n]);
      if (m.distance < kClearance) return Pinch{i, j, m.point};
    }
  return std::nullopt;
}

// The polygon splits at the pinch into two loops through its point, each with fewer vertices; the
// one with more area stays.
Polygon cutAtPinch(const Polygon& poly, const Pinch& pinch) {
  Polygon outer(poly.begin(), poly.begin() + std::ptrdiff_t(pinch.i + 1));
  outer.push_back(pinch.point);
  outer.insert(outer.end(), poly.begin() + std::ptrdiff_t(pinch.j + 1), poly.end());
  Polygon inner{pinch.point};
  inner.insert(inner.end(), poly.begin() + std::ptrdiff_t(pinch.i + 1),
               poly.begin() + std::ptrdiff_t(pinch.j + 1));
  return std::abs(signedArea(outer)) >= std::abs(signedArea(inner)) ? outer : inner;
}

// The finest approxPolyDP tolerance within the vertex budget; the count falls (not strictly) as the
// tolerance grows, so bisection finds it.
std::vector<cv::Point> simplifyContour(const std::vector<cv::Point>& contour, int vertices, double size) {
  if (contour.size() <= std::size_t(vertices)) return contour;
  std::vector<cv::Point> best, trial;
  cv::approxPolyDP(contour, best, size, true);
  double lo = 0, hi = size;
  for (int step = 0; step < 20; ++step) {
    const double mid = (lo + hi) / 2;
    cv::approxPolyDP(contour, trial, mid, true);
    if (trial.size() <= std::size_t(vertices)) {
      hi = mid;
      std::swap(best, trial);
    } else {
      lo = mid;
    }
  }
  return best;
}

}  // namespace

std::vector<Eigen::Vector2d> makeSimplePolygon(std::vector<Eigen::Vector2d> polygon) {
  std::erase_if(polygon, [](const Eigen::Vector2d& p) { return !p.allFinite(); });
  dropThinVertices(polygon);
  while (polygon.size() >= 3) {
    const std::optional<Pinch> pinch = firstPinch(polygon);
    if (!pinch) break;
    polygon = cutAtPinch(polygon, *pinch);
    dropThinVertices(polygon);
  }
  if (polygon.size() < 3) return {};
  if (signedArea(polygon) < 0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

std::vector<Eigen::Vector2d> normalizeContour(const std::vector<cv::Point>& contour, int vertices) {
  if (contour.size() < 3) return {};
  const cv::Rect box = cv::boundingRect(contour);
  if (box.width < 2 || box.height < 2) return {};
  const double sx = box.width - 1, sy = box.height - 1;
  Polygon polygon;
  for (const cv::Point& p : simplifyContour(contour, std::max(vertices, 3), std::max(sx, sy)))
    polygon.emplace_back((p.x - box.x) / sx - 0.5, 0.5 - (p.y - box.y) / sy);
  return makeSimplePolygon(std::move(polygon));
}

}  // namespace solidtex
