// CGAL translation unit: edge-collapse simplification.
#include "mesh/simplifyMesh.h"

#include <array>
#include <stdexcept>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_filter.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

namespace solidtex {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SMS = CGAL::Surface_mesh_simplification;

// A closed triangle mesh has 3/2 edges per triangle.
struct TriangleCount {
  std::size_t triangles;
  template <typename Profile>
  bool operator()(const double&, const Profile&, std::size_t, std::size_t edges) const {
    return 2 * edges <= 3 * triangles;
  }
};

}  // namespace

HullMesh simplifyMesh(const HullMesh& mesh, std::size_t triangles) {
  if (mesh.triangles.size() <= triangles) return mesh;
  Surface surface;
  for (const Eigen::Vector3d& v : mesh.vertices) surface.add_vertex({v.x(), v.y(), v.z()});
  for (const auto& [a, b, c] : mesh.triangles)
    if (surface.add_face(Surface::Vertex_index(a), Surface::Vertex_index(b), Surface::Vertex_index(c)) ==
        Surface::null_face())
      return mesh;
  SMS::GarlandHeckbert_plane_policies<Surface, Kernel> quadrics(surface);
  SMS::edge_collapse(surface, TriangleCount{triangles},
                     CGAL::parameters::get_cost(quadrics.get_cost())
                         .get_placement(quadrics.get_placement())
                         .filter(SMS::Bounded_normal_change_filter<>()));
  surface.collect_garbage();
  HullMesh out;
  out.vertices.reserve(surface.number_of_vertices());
  for (const Surface::Vertex_index v : surface.vertices()) {
    const Kernel::Point_3& p = surface.point(v);
    out.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (const Surface::Face_index f : surface.faces()) {
    std::array<int, 3> triangle{};
    int corner = 0;
    for (const Surface::Vertex_index v : surface.vertices_around_face(surface.halfedge(f))) {
      if (corner == 3)
        throw std::runtime_error("simplifyMesh: a collapse left a face that is not a triangle");
      triangle[std::size_t(corner++)] = int(v.idx());
    }
    out.triangles.push_back(triangle);
  }
  return out;
}

}  // namespace solidtex
