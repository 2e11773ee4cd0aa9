// CGAL translation unit: a mesh's connected pieces.
#include "mesh/largestPiece.h"

#include <algorithm>
#include <array>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Surface_mesh.h>
#include <Eigen/Geometry>

namespace solidtex {

HullMesh largestPiece(const HullMesh& mesh) {
  using Surface = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
  Surface surface;
  for (const Eigen::Vector3d& v : mesh.vertices) surface.add_vertex({v.x(), v.y(), v.z()});
  for (const auto& [a, b, c] : mesh.triangles)
    if (surface.add_face(Surface::Vertex_index(a), Surface::Vertex_index(b), Surface::Vertex_index(c)) ==
        Surface::null_face())
      return mesh;  // not a manifold surface: its pieces are not defined here
  auto piece = surface.add_property_map<Surface::Face_index, std::size_t>("f:piece").first;
  const std::size_t pieces = CGAL::Polygon_mesh_processing::connected_components(surface, piece);
  if (pieces <= 1) return mesh;
  std::vector<double> sixTimesVolume(pieces, 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& [a, b, c] = mesh.triangles[t];
    sixTimesVolume[piece[Surface::Face_index(Surface::size_type(t))]] +=
        mesh.vertices[std::size_t(a)].dot(mesh.vertices[std::size_t(b)].cross(mesh.vertices[std::size_t(c)]));
  }
  const std::size_t largest =
      std::size_t(std::max_element(sixTimesVolume.begin(), sixTimesVolume.end()) - sixTimesVolume.begin());
  HullMesh out;
  std::vector<int> renumbered(mesh.vertices.size(), -1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (piece[Surface::Face_index(Surface::size_type(t))] != largest) continue;
    std::array<int, 3> triangle = mesh.triangles[t];
    for (int& corner : triangle) {
      int& to = renumbered[std::size_t(corner)];
      if (to < 0) {
        to = int(out.vertices.size());
        out.vertices.push_back(mesh.vertices[std::size_t(corner)]);
      }
      corner = to;
    }
    out.triangles.push_back(triangle);
  }
  return out;
}

}  // namespace solidtex
