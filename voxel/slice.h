#pragma once
#include <cmath>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "common/Grid.h"
#include "common/SolidVolume.h"

namespace solidtex {

/// A rectangular window on a plane through a volume, in voxel coordinates: pixel (c, r) samples
/// the point origin + c*u + r*v (u, v orthonormal).
struct SlicePlane {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d u = Eigen::Vector3d::UnitX(), v = Eigen::Vector3d::UnitY();
  int width = 0, height = 0;
};

/// The plane k = index (axis 2), j = index (axis 1) or i = index (axis 0), covering the whole face.
SlicePlane axisPlane(const Dims& dims, int axis, int index);

/// The largest square window, centred on the volume's centre, of the plane through it with the
/// given normal that lies wholly inside the volume.
SlicePlane obliquePlane(const Dims& dims, const Eigen::Vector3d& normal, const Eigen::Vector3d& centre);

/// Nearest-voxel samples of a dense x-fastest field on the plane, row-major; samples outside the
/// volume get `outside`.
template <typename T>
std::vector<T> slice(const Dims& dims, const std::vector<T>& field, const SlicePlane& plane,
                     const T& outside) {
  std::vector<T> out(std::size_t(plane.width) * std::size_t(plane.height), outside);
  for (int r = 0; r < plane.height; ++r)
    for (int c = 0; c < plane.width; ++c) {
      const Eigen::Vector3d p = plane.origin + double(c) * plane.u + double(r) * plane.v;
      const int i = int(std::lround(p.x())), j = int(std::lround(p.y())), k = int(std::lround(p.z()));
      if (dims.contains(i, j, k))
        out[std::size_t(r) * std::size_t(plane.width) + std::size_t(c)] = field[dims.index(i, j, k)];
    }
  return out;
}

/// The volume's colour on the plane as an sRGB image (CV_32FC3, RGB order, [0,1]).
cv::Mat colorSlice(const SolidVolume& volume, const SlicePlane& plane);

}  // namespace solidtex
