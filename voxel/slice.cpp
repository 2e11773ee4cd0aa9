#include "voxel/slice.h"

#include <algorithm>

#include <Eigen/Geometry>

#include "common/srgb.h"

namespace solidtex {

SlicePlane axisPlane(const Dims& dims, int axis, int index) {
  SlicePlane plane;
  const int extent[3] = {dims.x, dims.y, dims.z};
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  // Keep the image's x along the lower remaining axis so the xy-slice reads like the photo.
  const int first = std::min(a, b), second = std::max(a, b);
  plane.origin = Eigen::Vector3d::Zero();
  plane.origin[axis] = index;
  plane.u = Eigen::Vector3d::Unit(first);
  plane.v = Eigen::Vector3d::Unit(second);
  plane.width = extent[first];
  plane.height = extent[second];
  return plane;
}

SlicePlane obliquePlane(const Dims& dims, const Eigen::Vector3d& normal, const Eigen::Vector3d& centre) {
  const Eigen::Vector3d n = normal.normalized();
  const Eigen::Vector3d helper = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  SlicePlane plane;
  plane.u = n.cross(helper).normalized();
  plane.v = n.cross(plane.u).normalized();
  // Half side h such that every corner centre +- h*u +- h*v stays inside [0, N-1].
  double half = 1e30;
  const double extent[3] = {double(dims.x - 1), double(dims.y - 1), double(dims.z - 1)};
  for (int a = 0; a < 3; ++a) {
    const double reach = std::abs(plane.u[a]) + std::abs(plane.v[a]);
    if (reach > 1e-12) half = std::min(half, std::min(centre[a], extent[a] - centre[a]) / reach);
  }
  const int side = std::max(1, int(std::floor(2 * half)) + 1);
  plane.width = plane.height = side;
  plane.origin = centre - (side - 1) * 0.5 * (plane.u + plane.v);
  return plane;
}

cv::Mat colorSlice(const SolidVolume& volume, const SlicePlane& plane) {
  cv::Mat image(plane.height, plane.width, CV_32FC3, cv::Scalar::all(0));
  for (int r = 0; r < plane.height; ++r)
    for (int c = 0; c < plane.width; ++c) {
      const Eigen::Vector3d p = plane.origin + double(c) * plane.u + double(r) * plane.v;
      const int i = int(std::lround(p.x())), j = int(std::lround(p.y())), k = int(std::lround(p.z()));
      if (!volume.dims.contains(i, j, k)) continue;
      const Rgb s = volume.colorAt(i, j, k);
      image.at<cv::Vec3f>(r, c) = {linearToSrgb(s[0]), linearToSrgb(s[1]), linearToSrgb(s[2])};
    }
  return image;
}

}  // namespace solidtex
