#include "validation/sectionStatistics.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "common/Random.h"
#include "common/randomDirection.h"
#include "voxel/slice.h"

namespace solidtex {
namespace {

struct PlaneSections {
  std::vector<double> areas;
  std::size_t particlePixels = 0, pixels = 0;
};

// Pixels of a plane's window that fall outside the volume.
constexpr std::int32_t kOutside = -1;

/// Labels 8-connected runs of equal particle ids by flood fill; one reused stack, no per-pixel allocation.
PlaneSections measurePlane(const std::vector<std::int32_t>& image, int width, int height, double minArea) {
  PlaneSections out;
  out.pixels = std::size_t(std::count_if(image.begin(), image.end(), [](std::int32_t id) { return id != kOutside; }));
  std::vector<std::uint8_t> seen(image.size(), 0);
  std::vector<int> stack;
  for (int start = 0; start < int(image.size()); ++start) {
    const std::int32_t id = image[std::size_t(start)];
    if (id <= 0 || seen[std::size_t(start)]) continue;
    std::size_t area = 0;
    bool edge = false;
    stack.assign(1, start);
    seen[std::size_t(start)] = 1;
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      ++area;
      const int x = p % width, y = p / width;
      const int neighbours[8][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1},
                                     {x - 1, y - 1}, {x + 1, y - 1}, {x - 1, y + 1}, {x + 1, y + 1}};
      for (const auto& [nx, ny] : neighbours) {
        if (nx < 0 || ny < 0 || nx >= width || ny >= height) {
          edge = true;
          continue;
        }
        const int q = ny * width + nx;
        edge |= image[std::size_t(q)] == kOutside;
        if (!seen[std::size_t(q)] && image[std::size_t(q)] == id) {
          seen[std::size_t(q)] = 1;
          stack.push_back(q);
        }
      }
    }
    out.particlePixels += area;
    if (!edge && double(area) >= minArea) out.areas.push_back(double(area));
  }
  return out;
}

/// The square window of the plane through `through` with this normal that covers the plane's whole
/// intersection with the volume: an inscribed window would cut the larger sections more often and
/// bias the areas small.
SlicePlane coveringPlane(const Dims& dims, const Eigen::Vector3d& normal, const Eigen::Vector3d& through) {
  SlicePlane plane = obliquePlane(dims, normal, through);
  const int side = int(std::ceil(std::sqrt(double(dims.x) * dims.x + double(dims.y) * dims.y + double(dims.z) * dims.z))) + 1;
  plane.width = plane.height = side;
  plane.origin = through - (side - 1) * 0.5 * (plane.u + plane.v);
  return plane;
}

std::vector<SlicePlane> planesFor(const Dims& dims, const SectionOptions& options) {
  std::vector<SlicePlane> planes;
  const int extent[3] = {dims.x, dims.y, dims.z};
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i < options.offsetsPerAxis; ++i)
      planes.push_back(axisPlane(dims, axis, int((i + 0.5) * extent[axis] / options.offsetsPerAxis)));
  Rng rng(deriveSeed(options.seed, 0x5EC7));
  const Eigen::Vector3d centre((dims.x - 1) * 0.5, (dims.y - 1) * 0.5, (dims.z - 1) * 0.5);
  const double spread = 0.25 * std::min({dims.x, dims.y, dims.z});
  for (int i = 0; i < options.obliquePlanes; ++i) {
    const Eigen::Vector3d normal = randomDirection(rng);
    // Off-centre planes along the normal sample particles at every depth, not only the middle.
    const Eigen::Vector3d through = centre + (2 * uniform01(rng) - 1) * spread * normal;
    planes.push_back(coveringPlane(dims, normal, through));
  }
  return planes;
}

} // namespace

SectionStatistics sampleSections(const Dims& dims, const std::vector<std::int32_t>& ids, const SectionOptions& options) {
  const std::vector<SlicePlane> planes = planesFor(dims, options);
  std::vector<PlaneSections> perPlane(planes.size());
  tbb::parallel_for(std::size_t(0), planes.size(), [&](std::size_t i) {
    const SlicePlane& plane = planes[i];
    perPlane[i] = measurePlane(slice(dims, ids, plane, kOutside), plane.width, plane.height, options.minArea);
  });
  SectionStatistics stats;
  std::size_t particlePixels = 0, pixels = 0;
  for (const auto& p : perPlane) {
    stats.areas.insert(stats.areas.end(), p.areas.begin(), p.areas.end());
    particlePixels += p.particlePixels;
    pixels += p.pixels;
  }
  stats.planes = int(planes.size());
  stats.areaFraction = pixels ? double(particlePixels) / double(pixels) : 0;
  return stats;
}

double ksStatistic(std::vector<double> a, std::vector<double> b) {
  if (a.empty() || b.empty()) return 1;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  std::size_t i = 0, j = 0;
  double gap = 0;
  while (i < a.size() && j < b.size()) {
    const double x = std::min(a[i], b[j]);
    while (i < a.size() && a[i] <= x) ++i;
    while (j < b.size() && b[j] <= x) ++j;
    gap = std::max(gap, std::abs(double(i) / double(a.size()) - double(j) / double(b.size())));
  }
  return gap;
}

double wasserstein1(std::vector<double> a, std::vector<double> b) {
  if (a.empty() || b.empty()) return 0;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  // Integrate |F_a - F_b| over the merged breakpoints.
  std::size_t i = 0, j = 0;
  double x = std::min(a.front(), b.front()), distance = 0;
  while (i < a.size() || j < b.size()) {
    const double next = j >= b.size() || (i < a.size() && a[i] <= b[j]) ? a[i] : b[j];
    distance += std::abs(double(i) / double(a.size()) - double(j) / double(b.size())) * (next - x);
    x = next;
    while (i < a.size() && a[i] <= x) ++i;
    while (j < b.size() && b[j] <= x) ++j;
  }
  return distance;
}

} // namespace solidtex
