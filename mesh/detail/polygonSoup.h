#pragma once
// Internal: a HullMesh as the polygon soup CGAL's Polygon Mesh Processing reads.
#include <cstddef>
#include <vector>

#include "particles/HullMesh.h"

namespace solidtex::mesh::detail {

template <typename Point>
struct PolygonSoup {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
};

template <typename Point>
PolygonSoup<Point> polygonSoupOf(const HullMesh& mesh) {
  PolygonSoup<Point> soup;
  soup.points.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& v : mesh.vertices) soup.points.emplace_back(v.x(), v.y(), v.z());
  soup.polygons.reserve(mesh.triangles.size());
  for (const auto& [a, b, c] : mesh.triangles)
    soup.polygons.push_back({std::size_t(a), std::size_t(b), std::size_t(c)});
  return soup;
}

}  // namespace solidtex::mesh::detail
