#include "particles/HullMesh.h"

#include <limits>

#include <Eigen/Geometry>

namespace solidtex {

double HullMesh::volume() const {
  double sixTimes = 0;
  for (const auto& [a, b, c] : triangles)
    sixTimes += vertices[std::size_t(a)].dot(vertices[std::size_t(b)].cross(vertices[std::size_t(c)]));
  return sixTimes / 6;
}

Eigen::Vector3d HullMesh::boxMin() const {
  if (vertices.empty()) return Eigen::Vector3d::Zero();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  for (const Eigen::Vector3d& v : vertices) lo = lo.cwiseMin(v);
  return lo;
}

Eigen::Vector3d HullMesh::boxMax() const {
  if (vertices.empty()) return Eigen::Vector3d::Zero();
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  for (const Eigen::Vector3d& v : vertices) hi = hi.cwiseMax(v);
  return hi;
}

}  // namespace solidtex
