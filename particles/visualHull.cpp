// The only CGAL translation unit of the particles module: exact corefinement of silhouette prisms.
#include "particles/visualHull.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <Eigen/LU>

namespace solidtex {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactMesh = CGAL::Surface_mesh<EK::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

// Prism caps sit beyond the cube's corners (sqrt(3)/2 from the centre), so only prism sides cut the cube.
constexpr double kHalfLength = 1.0;

void checkRotation(const Eigen::Matrix3d& r) {
  if (!r.allFinite() || (r.transpose() * r - Eigen::Matrix3d::Identity()).norm() > 1e-6 ||
      r.determinant() < 0)
    throw std::invalid_argument("visualHull: a view's rotation is not a proper rotation matrix");
}

// Prism corners snap to multiples of 2^-16 (of the local cube): short dyadic inputs keep the exact
// rationals of the intersection points short, and those are most of corefinement's cost (its
// degenerate orientation tests fall back to them). ~1.6x faster than raw doubles.
constexpr int kSnapBits = 16;

double snap(double x) { return std::ldexp(std::round(std::ldexp(x, kSnapBits)), -kSnapBits); }

EK::Point_3 exactPoint(const Eigen::Vector3d& p) { return {snap(p.x()), snap(p.y()), snap(p.z())}; }

ExactMesh cube() {
  ExactMesh mesh;
  std::vector<ExactMesh::Vertex_index> v;
  for (int i = 0; i < 8; ++i)
    v.push_back(mesh.add_vertex(exactPoint({i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5})));
  for (const auto& [a, b, c, d] : {std::array{0, 4, 6, 2}, std::array{1, 3, 7, 5}, std::array{0, 1, 5, 4},
                                   std::array{2, 6, 7, 3}, std::array{0, 2, 3, 1}, std::array{4, 5, 7, 6}})
    mesh.add_face(v[a], v[b], v[c], v[d]);
  PMP::triangulate_faces(mesh);
  return mesh;
}

// The silhouette's polygon extruded along its viewing direction; empty when the polygon has no area.
ExactMesh prism(const Silhouette& view) {
  const std::vector<Eigen::Vector2d> poly = makeSimplePolygon(view.polygon);
  ExactMesh mesh;
  if (poly.empty()) return mesh;
  std::vector<ExactMesh::Vertex_index> bottom, top;
  for (const Eigen::Vector2d& q : poly) {
    bottom.push_back(
        mesh.add_vertex(exactPoint(view.rotation * Eigen::Vector3d(q.x(), q.y(), -kHalfLength))));
    top.push_back(mesh.add_vertex(exactPoint(view.rotation * Eigen::Vector3d(q.x(), q.y(), kHalfLength))));
  }
  mesh.add_face(std::vector(bottom.rbegin(), bottom.rend()));
  mesh.add_face(top);
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const std::size_t next = (k + 1) % poly.size();
    mesh.add_face(bottom[k], bottom[next], top[next], top[k]);
  }
  PMP::triangulate_faces(mesh);
  return mesh;
}

// Rounded from the exact value: a lazy number's own approximation depends on which exact
// evaluations happened to run, which is not reproducible.
Eigen::Vector3d rounded(const EK::Point_3& p) {
  const auto& e = CGAL::exact(p);
  return {CGAL::to_double(e.x()), CGAL::to_double(e.y()), CGAL::to_double(e.z())};
}

// Corefinement numbers vertices and faces in an order that depends on memory addresses, so the
// output is put in a canonical order: vertices sorted by their exact coordinates, each triangle
// starting at its smallest vertex, triangles sorted. Same hull, same bits, at any thread count.
HullMesh toHullMesh(const ExactMesh& mesh) {
  std::vector<ExactMesh::Vertex_index> order(mesh.vertices().begin(), mesh.vertices().end());
  std::sort(order.begin(), order.end(),
            [&](auto a, auto b) { return CGAL::compare_xyz(mesh.point(a), mesh.point(b)) == CGAL::SMALLER; });
  std::vector<int> rank(mesh.num_vertices(), -1);  // by index, removed vertices included
  HullMesh out;
  for (const auto v : order) {
    rank[v.idx()] = int(out.vertices.size());
    out.vertices.push_back(rounded(mesh.point(v)));
  }
  for (const auto f : mesh.faces()) {
    std::array<int, 3> tri{};
    int corner = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      tri[std::size_t(corner++)] = rank[v.idx()];
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    out.triangles.push_back(tri);
  }
  std::sort(out.triangles.begin(), out.triangles.end());
  return out;
}

}  // namespace

HullMesh visualHull(const std::vector<Silhouette>& views) {
  for (const Silhouette& view : views) checkRotation(view.rotation);
  ExactMesh hull = cube();
  for (const Silhouette& view : views) {
    ExactMesh carver = prism(view);
    if (carver.number_of_faces() == 0) return {};
    // false means the intersection would not be a manifold: no usable hull either.
    if (!PMP::corefine_and_compute_intersection(hull, carver, hull) || hull.number_of_faces() == 0) return {};
  }
  return toHullMesh(hull);
}

}  // namespace solidtex
