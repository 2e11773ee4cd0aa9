#include "validation/sectionStatistics.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "common/Error.h"
#include "common/Random.h"
#include "common/randomDirection.h"
#include "segmentation/resampleRegions.h"
#include "validation/arrangement.h"
#include "voxel/slice.h"

namespace solidtex {
namespace {

// Pixels of a plane's window that fall outside the volume.
constexpr std::int32_t kOutside = -1;

struct Region {
  std::vector<cv::Point> pixels;
  bool cut = false;  // touches the image's edge or the volume's walls
};

/// Visits the 8-connected regions of equal positive labels by flood fill, one reused stack.
template <typename Visit>
void forEachRegion(const cv::Mat& labels, Visit&& visit) {
  const int width = labels.cols, height = labels.rows;
  std::vector<std::uint8_t> seen(std::size_t(width) * std::size_t(height), 0);
  std::vector<cv::Point> stack;
  Region region;
  for (int y0 = 0; y0 < height; ++y0)
    for (int x0 = 0; x0 < width; ++x0) {
      const std::int32_t id = labels.at<std::int32_t>(y0, x0);
      if (id <= 0 || seen[std::size_t(y0) * width + x0]) continue;
      region.pixels.clear();
      region.cut = false;
      stack.assign(1, {x0, y0});
      seen[std::size_t(y0) * width + x0] = 1;
      while (!stack.empty()) {
        const cv::Point p = stack.back();
        stack.pop_back();
        region.pixels.push_back(p);
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = p.x + dx, ny = p.y + dy;
            if (nx < 0 || ny < 0 || nx >= width || ny >= height) {
              region.cut = true;
              continue;
            }
            const std::int32_t neighbour = labels.at<std::int32_t>(ny, nx);
            region.cut |= neighbour == kOutside;
            if (neighbour == id && !seen[std::size_t(ny) * width + nx]) {
              seen[std::size_t(ny) * width + nx] = 1;
              stack.push_back({nx, ny});
            }
          }
      }
      visit(region);
    }
}

// One image's measures and the pixel counts behind its area fraction, which add up over planes.
struct ImageMeasures {
  SectionStatistics stats;
  std::size_t particlePixels = 0, pixels = 0;  // pixels inside the volume
};

/// Every measure of one image; arrangement measures only where the whole window lies in the volume.
ImageMeasures measureImage(const cv::Mat& labels, bool axisAligned, const SectionOptions& options) {
  ImageMeasures measures;
  SectionStatistics& out = measures.stats;
  out.planes = 1;
  std::vector<cv::Point2d> centres;
  std::vector<bool> counted;
  for (int y = 0; y < labels.rows; ++y)
    for (int x = 0; x < labels.cols; ++x) {
      const std::int32_t id = labels.at<std::int32_t>(y, x);
      measures.pixels += id != kOutside;
      measures.particlePixels += id > 0;
    }
  forEachRegion(labels, [&](const Region& region) {
    const double area = double(region.pixels.size());
    if (area < options.minArea) return;
    if (!region.cut) out.areas.push_back(area);
    if (!axisAligned) return;  // an oblique sampling grid adds jagged edges that no photo has
    if (!region.cut && area >= options.shapeMinArea) out.shapes.push_back(measureRegion(region.pixels));
    cv::Point2d sum(0, 0);
    for (const cv::Point& p : region.pixels) sum += cv::Point2d(p);
    centres.push_back(sum / area);
    counted.push_back(!region.cut);
  });
  out.areaFraction = measures.pixels ? double(measures.particlePixels) / double(measures.pixels) : 0;
  if (axisAligned && options.windowSide > 0) {
    out.windowFractions = windowFractions(labels, options.windowSide);
    out.neighbourDistances = nearestNeighbourDistances(centres, counted, labels.size());
  }
  return measures;
}

/// The square window of the plane through `through` with this normal that covers the plane's whole
/// intersection with the volume: an inscribed window would cut the larger sections more often and
/// bias the areas small.
SlicePlane coveringPlane(const Dims& dims, const Eigen::Vector3d& normal, const Eigen::Vector3d& through,
                         double step) {
  SlicePlane plane = obliquePlane(dims, normal, through);
  const double diagonal =
      std::sqrt(double(dims.x) * dims.x + double(dims.y) * dims.y + double(dims.z) * dims.z);
  plane.width = plane.height = int(std::ceil(diagonal / step)) + 1;
  plane.u *= step;
  plane.v *= step;
  plane.origin = through - (plane.width - 1) * 0.5 * (plane.u + plane.v);
  return plane;
}

SlicePlane steppedAxisPlane(const Dims& dims, int axis, int index, double step) {
  SlicePlane plane = axisPlane(dims, axis, index);
  plane.width = int((plane.width - 1) / step) + 1;
  plane.height = int((plane.height - 1) / step) + 1;
  plane.u *= step;
  plane.v *= step;
  return plane;
}

int axisPlaneCount(const SectionOptions& options) {
  return (options.planeAxis < 0 ? 3 : 1) * options.offsetsPerAxis;
}

// Axis plane i of the axisPlaneCount, sampled `step` voxels apart.
SlicePlane axisPlaneNumber(const Dims& dims, const SectionOptions& options, int i, double step) {
  const int extent[3] = {dims.x, dims.y, dims.z};
  const int axis = options.planeAxis < 0 ? i / options.offsetsPerAxis : options.planeAxis;
  const int offset = i % options.offsetsPerAxis;
  return steppedAxisPlane(dims, axis, int((offset + 0.5) * extent[axis] / options.offsetsPerAxis), step);
}

std::vector<SlicePlane> planesFor(const Dims& dims, const SectionOptions& options) {
  std::vector<SlicePlane> planes;
  for (int i = 0; i < axisPlaneCount(options); ++i)
    planes.push_back(axisPlaneNumber(dims, options, i, options.step));
  Rng rng(deriveSeed(options.seed, 0x5EC7));
  const Eigen::Vector3d centre((dims.x - 1) * 0.5, (dims.y - 1) * 0.5, (dims.z - 1) * 0.5);
  const double spread = 0.25 * std::min({dims.x, dims.y, dims.z});
  for (int i = 0; i < options.obliquePlanes; ++i) {
    const Eigen::Vector3d normal = randomDirection(rng);
    // Off-centre planes along the normal sample particles at every depth, not only the middle.
    const Eigen::Vector3d through = centre + (2 * uniform01(rng) - 1) * spread * normal;
    planes.push_back(coveringPlane(dims, normal, through, options.step));
  }
  return planes;
}

}  // namespace

int planeAxisOf(const std::string& plane) {
  if (plane == "yz") return 0;
  if (plane == "xz") return 1;
  if (plane == "xy") return 2;
  throw OptionError("unknown plane '" + plane + "': use xy, xz or yz");
}

std::string planeNameOf(int axis) {
  constexpr const char* names[3] = {"yz", "xz", "xy"};
  return names[axis];
}

SectionStatistics sampleSections(const Dims& dims, const std::vector<std::int32_t>& ids,
                                 const SectionOptions& options) {
  const std::vector<SlicePlane> planes = planesFor(dims, options);
  const auto axisPlanes = std::size_t(axisPlaneCount(options));
  std::vector<ImageMeasures> perPlane(planes.size());
  tbb::parallel_for(std::size_t(0), planes.size(), [&](std::size_t i) {
    const bool axisAligned = i < axisPlanes;
    SlicePlane plane = planes[i];
    // Axis planes of a finer volume are cut at its own resolution and resampled by area, as a
    // camera at the coarser one would see them: nearest-voxel steps would give jagged edges.
    const bool resample = axisAligned && options.step != 1;
    if (resample) plane = axisPlaneNumber(dims, options, int(i), 1);
    std::vector<std::int32_t> image = slice(dims, ids, plane, kOutside);
    cv::Mat labels(plane.height, plane.width, CV_32S, image.data());
    if (resample) labels = resampleLabels(labels, 1 / options.step);
    perPlane[i] = measureImage(labels, axisAligned, options);
  });
  SectionStatistics stats;
  std::size_t particlePixels = 0, pixels = 0;
  const auto append = [](auto& to, const auto& from) { to.insert(to.end(), from.begin(), from.end()); };
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const SectionStatistics& p = perPlane[i].stats;
    append(stats.areas, p.areas);
    append(stats.shapes, p.shapes);
    append(stats.windowFractions, p.windowFractions);
    append(stats.neighbourDistances, p.neighbourDistances);
    particlePixels += perPlane[i].particlePixels;
    pixels += perPlane[i].pixels;
  }
  stats.planes = int(planes.size());
  stats.areaFraction = pixels ? double(particlePixels) / double(pixels) : 0;
  return stats;
}

SectionStatistics measureLabelImage(const cv::Mat& labels, const SectionOptions& options) {
  CV_Assert(labels.type() == CV_32S);
  return measureImage(labels, true, options).stats;
}

}  // namespace solidtex
