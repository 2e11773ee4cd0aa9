// CGAL translation unit: manifoldness and closure of a triangle soup.
#include "mesh/meshTopology.h"

#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include "mesh/detail/polygonSoup.h"

namespace solidtex {

MeshTopology meshTopology(const HullMesh& mesh) {
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  namespace PMP = CGAL::Polygon_mesh_processing;
  const auto soup = mesh::detail::polygonSoupOf<Point>(mesh);
  MeshTopology topology;
  // A soup is a polygon mesh when its edges are manifold and consistently wound and its vertices
  // are manifold.
  if (mesh.triangles.empty() || !PMP::is_polygon_soup_a_polygon_mesh(soup.polygons)) return topology;
  CGAL::Surface_mesh<Point> surface;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, surface);
  topology.manifold = true;
  topology.closed = CGAL::is_closed(surface);
  auto component = surface.add_property_map<CGAL::Surface_mesh<Point>::Face_index, std::size_t>("f:c").first;
  topology.components = int(PMP::connected_components(surface, component));
  return topology;
}

}  // namespace solidtex
