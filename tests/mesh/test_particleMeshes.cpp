#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include "mesh/detail/polygonSoup.h"
#include "mesh/meshTopology.h"
#include "mesh/particleMeshes.h"
#include "placement/cropToCountedBox.h"
#include "segmentation/analyzeExemplar.h"

namespace solidtex {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface = CGAL::Surface_mesh<Kernel::Point_3>;

Surface surfaceOf(const HullMesh& mesh) {
  const auto soup = mesh::detail::polygonSoupOf<Kernel::Point_3>(mesh);
  Surface surface;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, surface);
  return surface;
}

using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Surface>>>;

// What the volume's faces are: walls; open (placed with a margin and cut out, as the open boundary
// does); periodic (a torus, particles wrap).
enum class Faces { Walls, Open, Periodic };

struct MeshCase {
  std::string photo;
  double smoothing;  // HullSmoothing::radius; 0: the sharp visual hulls
  Faces faces;
};

const char* facesName(Faces faces) {
  return faces == Faces::Walls ? "walls" : faces == Faces::Open ? "open" : "periodic";
}

void PrintTo(const MeshCase& c, std::ostream* out) {
  *out << c.photo << " smoothing " << c.smoothing << " " << facesName(c.faces);
}

std::string caseName(const testing::TestParamInfo<MeshCase>& info) {
  return info.param.photo + (info.param.smoothing > 0 ? "_smooth_" : "_sharp_") + facesName(info.param.faces);
}

class MeshesOfSolid : public testing::TestWithParam<MeshCase> {};

// The photo's largest particle a fifth of the volume's edge.
double voxelsPerPixelFor(const ExemplarStats& stats, int edge) {
  int largest = 1;
  for (const Particle2D& p : stats.particles) largest = std::max({largest, p.box.width, p.box.height});
  return std::min(1.0, 0.2 * edge / largest);
}

constexpr int kParticles = 400;  // the largest first: the smallest photo particles are a few voxels

PlacementResult placeSolid(const ExemplarStats& stats, const ParticleFactory& factory, const Dims& dims,
                           Faces faces) {
  const bool open = faces == Faces::Open, periodic = faces == Faces::Periodic;
  const int margin = open ? 8 : 0;
  const Dims placed{dims.x + 2 * margin, dims.y + 2 * margin, dims.z + 2 * margin};
  const auto field = makeSpaciousnessField(PlacerKind::Edt, placed, 40, periodic);
  PlacementOptions options;
  options.dims = placed;
  options.periodic = periodic;
  options.voxelsPerPixel = voxelsPerPixelFor(stats, dims.x);
  options.maxParticles = kParticles;
  if (open) options.counted = Box::at({margin, margin, margin}, dims);
  PlacementResult result = placeLargestFirst(stats, factory, *field, options);
  return open ? cropToCountedBox(std::move(result)) : result;
}

// The voxels of the box around both a particle and its mesh; in a periodic volume, where they run past
// the faces too.
std::array<Voxel, 2> regionOf(const PlacedParticle& p, const HullMesh& mesh, const Dims& dims,
                              bool periodic) {
  const Eigen::Vector3d lo = mesh.boxMin(), hi = mesh.boxMax();
  const Voxel from{std::min(p.origin.x, int(std::floor(lo.x()))),
                   std::min(p.origin.y, int(std::floor(lo.y()))),
                   std::min(p.origin.z, int(std::floor(lo.z())))};
  const Voxel to{std::max(p.origin.x + p.box.x, int(std::ceil(hi.x()))),
                 std::max(p.origin.y + p.box.y, int(std::ceil(hi.y()))),
                 std::max(p.origin.z + p.box.z, int(std::ceil(hi.z())))};
  if (periodic) return {from, to};
  return {Voxel{std::max(0, from.x), std::max(0, from.y), std::max(0, from.z)},
          Voxel{std::min(dims.x - 1, to.x), std::min(dims.y - 1, to.y), std::min(dims.z - 1, to.z)}};
}

// Every mesh of a 64^3 solid is closed, 2-manifold, outward and inside the volume (in a periodic one,
// whole, running past the faces where its particle wraps), and encloses its particle's voxel centres. The
// voxels inside a mesh but not in its particle are the thin parts voxelize drops, in the mesh's boundary
// shell: within a voxel of its surface.
TEST_P(MeshesOfSolid, AreClosedInsideAndVoxelizeToTheirParticles) {
  const MeshCase& c = GetParam();
  const ExemplarStats stats =
      analyzeExemplar(std::string(SOLIDTEX_DATA_DIR) + "/particles/" + c.photo + ".png", {});
  ParticleOptions options;
  options.shapes = 12;
  options.smoothing.radius = c.smoothing;
  const ParticleFactory factory(stats, options);
  const Dims dims{64, 64, 64};
  const bool periodic = c.faces == Faces::Periodic;
  const PlacementResult result = placeSolid(stats, factory, dims, c.faces);
  ASSERT_GT(result.particles.size(), 30u);

  const std::vector<ParticleMesh> meshes = particleMeshes(result, factory.hulls());
  ASSERT_EQ(meshes.size(), result.particles.size());
  std::size_t voxels = 0, outsideMesh = 0, meshOnly = 0, beyondShell = 0;
  double farthest = 0, farthestOutside = 0;  // of a mesh-only (particle-only) voxel centre from the surface
  int wrapping = 0;
  const Eigen::Array3d size(dims.x, dims.y, dims.z);
  for (const ParticleMesh& m : meshes) {
    SCOPED_TRACE("particle " + std::to_string(m.id));
    EXPECT_TRUE(meshTopology(m.surface).closed);
    EXPECT_GT(m.surface.volume(), 0);  // outward
    const Eigen::Array3d lo = m.surface.boxMin().array(), hi = m.surface.boxMax().array();
    const bool inside = (lo >= -0.5 - 1e-9).all() && (hi <= size - 0.5 + 1e-9).all();
    if (periodic) {
      wrapping += !inside;
      EXPECT_TRUE((hi - lo < size).all());                        // its copies do not meet
      EXPECT_TRUE((hi > -0.5).all() && (lo < size - 0.5).all());  // it starts inside the volume
    } else {
      EXPECT_TRUE(inside);
    }

    const Surface surface = surfaceOf(m.surface);
    const CGAL::Side_of_triangle_mesh<Surface, Kernel> side(surface);
    const Tree tree(faces(surface).first, faces(surface).second, surface);
    const auto [from, to] = regionOf(result.particles[std::size_t(m.id - 1)], m.surface, dims, periodic);
    for (int z = from.z; z <= to.z; ++z)
      for (int y = from.y; y <= to.y; ++y)
        for (int x = from.x; x <= to.x; ++x) {
          const Kernel::Point_3 centre(x, y, z);
          const bool mine = result.ids[dims.index(dims.wrap({x, y, z}))] == m.id;
          const bool inMesh = side(centre) == CGAL::ON_BOUNDED_SIDE;
          voxels += mine;
          if (mine == inMesh) continue;
          const double distance = std::sqrt(tree.squared_distance(centre));
          if (mine) {
            ++outsideMesh;
            farthestOutside = std::max(farthestOutside, distance);
          } else {
            ++meshOnly;
            farthest = std::max(farthest, distance);
            beyondShell += distance > 1;
          }
        }
  }
  std::printf(
      "%zu particles, %zu voxels: %zu outside their meshes, at most %.3f from the surface; %zu more "
      "inside them, at most %.3f from the surface, %zu beyond one voxel\n",
      meshes.size(), voxels, outsideMesh, farthestOutside, meshOnly, farthest, beyondShell);
  // Simplified to edges of about 1.4 voxels, a surface curved over a voxel or more moves by at most
  // (1.4)^2 / 8 = 1/4 voxel: only centres that close to it change sides.
  EXPECT_LE(farthestOutside, 0.25);
  // A thin part falls apart between voxel centres where it is under about a voxel thick; a few
  // centres behind a thin neck lie a little deeper.
  EXPECT_LE(double(beyondShell), 1e-3 * double(voxels));
  EXPECT_LT(double(meshOnly), 0.03 * double(voxels));
  if (periodic) {
    EXPECT_GT(wrapping, 10) << "few particles cross a face: the case tests little";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Photos, MeshesOfSolid,
    testing::Values(MeshCase{"gravel", 0, Faces::Walls}, MeshCase{"gravel", 0.12, Faces::Open},
                    MeshCase{"smarties", 0.12, Faces::Walls}, MeshCase{"coins", 0, Faces::Open},
                    MeshCase{"leopard", 0.12, Faces::Open}, MeshCase{"coins", 0.12, Faces::Periodic}),
    caseName);

TEST(ParticleMeshes, RefuseAParticleWithoutItsHull) {
  PlacementResult placement;
  placement.dims = {4, 4, 4};
  placement.particles.push_back({});
  EXPECT_THROW(particleMeshes(placement, {}), std::invalid_argument);
}

}  // namespace
}  // namespace solidtex
