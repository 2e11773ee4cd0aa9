// CGAL translation unit: exact corefinement of a particle's surface with the volume's box.
#include "mesh/clipToBox.h"

#include <array>
#include <stdexcept>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include "mesh/detail/polygonSoup.h"

namespace solidtex {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactMesh = CGAL::Surface_mesh<EK::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

ExactMesh exactMeshOf(const HullMesh& mesh) {
  const auto soup = mesh::detail::polygonSoupOf<EK::Point_3>(mesh);
  if (!PMP::is_polygon_soup_a_polygon_mesh(soup.polygons))
    throw std::runtime_error("clipToBox: the mesh is not a manifold surface");
  ExactMesh exact;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, exact);
  if (!CGAL::is_closed(exact)) throw std::runtime_error("clipToBox: the mesh is not closed");
  return exact;
}

HullMesh hullMeshOf(ExactMesh& exact) {
  exact.collect_garbage();  // vertex indices 0..n-1, as the HullMesh's
  HullMesh mesh;
  for (const ExactMesh::Vertex_index v : exact.vertices()) {
    const EK::Point_3& p = exact.point(v);
    mesh.vertices.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  for (const ExactMesh::Face_index f : exact.faces()) {
    std::array<int, 3> triangle{};
    int corner = 0;
    for (const ExactMesh::Vertex_index v : exact.vertices_around_face(exact.halfedge(f))) {
      if (corner == 3) throw std::runtime_error("clipToBox: the cut left a face that is not a triangle");
      triangle[std::size_t(corner++)] = int(v.idx());
    }
    if (corner != 3) throw std::runtime_error("clipToBox: the cut left a face that is not a triangle");
    mesh.triangles.push_back(triangle);
  }
  return mesh;
}

}  // namespace

HullMesh clipToBox(const HullMesh& mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const Eigen::Vector3d meshLo = mesh.boxMin(), meshHi = mesh.boxMax();
  if ((meshLo.array() >= lo.array()).all() && (meshHi.array() <= hi.array()).all()) return mesh;
  if ((meshHi.array() <= lo.array()).any() || (meshLo.array() >= hi.array()).any()) return {};
  ExactMesh exact = exactMeshOf(mesh);
  const EK::Iso_cuboid_3 box(EK::Point_3(lo.x(), lo.y(), lo.z()), EK::Point_3(hi.x(), hi.y(), hi.z()));
  if (!PMP::clip(exact, box, CGAL::parameters::clip_volume(true).throw_on_self_intersection(true)))
    throw std::runtime_error("clipToBox: the cut surface is not manifold");
  return hullMeshOf(exact);
}

}  // namespace solidtex
