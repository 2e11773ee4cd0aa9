#pragma once
#include <Eigen/Core>

#include "particles/HullMesh.h"

namespace solidtex::test {

/// The box [lo, hi] as 12 outward triangles.
inline HullMesh boxMesh(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  HullMesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}

}  // namespace solidtex::test
