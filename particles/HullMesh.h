#pragma once
#include <array>
#include <vector>

#include <Eigen/Core>

namespace solidtex {

/// A closed, outward-oriented triangle mesh (plain data; CGAL stays in the .cpp files).
struct HullMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  double volume() const;
  Eigen::Vector3d boxMin() const;
  Eigen::Vector3d boxMax() const;
};

}  // namespace solidtex
