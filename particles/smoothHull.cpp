#include "particles/smoothHull.h"

#include <algorithm>
#include <cmath>

#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <opencv2/imgproc.hpp>

#include "particles/voxelizeHull.h"

namespace solidtex {
namespace {

// The hull voxelized with `resolution` voxels across its largest side and `pad` empty voxels around:
// 1 inside, 0 outside, as z-slices of a (z, y * x) matrix. `origin` and `step` take voxel indices back
// to the hull's coordinates.
cv::Mat insideOf(const HullMesh& hull, int resolution, int pad, Eigen::Vector3i& sides,
                 Eigen::Vector3d& origin, Eigen::Vector3d& step) {
  const Eigen::Vector3d lo = hull.boxMin(), extent = hull.boxMax() - lo;
  Eigen::Vector3i inner;
  for (int a = 0; a < 3; ++a)
    inner[a] = std::max(2, int(std::lround(resolution * extent[a] / extent.maxCoeff())));
  const VoxelShape shape = voxelize(hull, Eigen::Matrix3d::Identity(), inner.x(), inner.y(), inner.z());
  step = extent.cwiseQuotient(inner.cast<double>());
  origin = lo + 0.5 * step - double(pad) * step;  // index (0,0,0): the centre of the padded corner voxel
  sides = inner.array() + 2 * pad;
  cv::Mat volume = cv::Mat::zeros(sides.z(), sides.y() * sides.x(), CV_32F);
  for (int k = 0; k < shape.dims.z; ++k)
    for (int j = 0; j < shape.dims.y; ++j)
      for (int i = 0; i < shape.dims.x; ++i)
        if (shape.inside[shape.dims.index(i, j, k)])
          volume.at<float>(k + pad, (j + pad) * sides.x() + i + pad) = 1.0f;
  return volume;
}

// Separable 3D Gaussian: each z-slice in x and y, then every (x, y) column along z.
void gaussianBlur3d(cv::Mat& volume, const Eigen::Vector3i& sides, double sigma) {
  const int reach = int(std::ceil(3 * sigma));
  for (int k = 0; k < sides.z(); ++k) {
    cv::Mat slice(sides.y(), sides.x(), CV_32F, volume.ptr<float>(k));
    cv::GaussianBlur(slice, slice, cv::Size(2 * reach + 1, 2 * reach + 1), sigma, sigma, cv::BORDER_CONSTANT);
  }
  cv::GaussianBlur(volume, volume, cv::Size(1, 2 * reach + 1), 0, sigma, cv::BORDER_CONSTANT);
}

}  // namespace

HullMesh smoothHull(const HullMesh& hull, const HullSmoothing& smoothing) {
  const int resolution = std::max(8, smoothing.resolution);
  const double sigma = smoothing.radius * resolution;
  if (hull.triangles.empty() || sigma < 0.5) return hull;
  Eigen::Vector3i sides;
  Eigen::Vector3d origin, step;
  const int pad = int(std::ceil(3 * sigma)) + 1;  // the filter's reach, and a voxel to close the surface
  cv::Mat volume = insideOf(hull, resolution, pad, sides, origin, step);
  // Blurring the inside indicator and cutting it at one half moves flat parts little and rounds edges
  // and corners over about sigma.
  gaussianBlur3d(volume, sides, sigma);

  openvdb::initialize();
  const openvdb::CoordBBox box(openvdb::Coord(0),
                               openvdb::Coord(sides.x() - 1, sides.y() - 1, sides.z() - 1));
  const openvdb::tools::Dense<float, openvdb::tools::LayoutXYZ> dense(box, volume.ptr<float>());
  auto grid = openvdb::FloatGrid::create(0.0f);
  openvdb::tools::copyFromDense(dense, *grid, 0.0f);
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, points, triangles, quads, 0.5);

  HullMesh out;
  for (const openvdb::Vec3s& p : points)
    out.vertices.push_back(origin + Eigen::Vector3d(p.x(), p.y(), p.z()).cwiseProduct(step));
  for (const openvdb::Vec3I& t : triangles) out.triangles.push_back({int(t.x()), int(t.y()), int(t.z())});
  for (const openvdb::Vec4I& q : quads) {
    out.triangles.push_back({int(q.x()), int(q.y()), int(q.z())});
    out.triangles.push_back({int(q.x()), int(q.z()), int(q.w())});
  }
  // volumeToMesh winds its polygons one way for every volume; make them face outward.
  if (out.volume() < 0)
    for (auto& t : out.triangles) std::swap(t[1], t[2]);
  return out.triangles.empty() ? hull : out;
}

}  // namespace solidtex
