#include <gtest/gtest.h>

#include "mesh/clipToBox.h"
#include "mesh/meshTopology.h"
#include "tests/mesh/cube.h"

namespace solidtex {
namespace {

using test::boxMesh;
using V = Eigen::Vector3d;

TEST(MeshTopology, BoxIsClosedAndManifold) {
  const MeshTopology t = meshTopology(boxMesh(V(0, 0, 0), V(1, 2, 3)));
  EXPECT_TRUE(t.manifold);
  EXPECT_TRUE(t.closed);
  EXPECT_EQ(t.components, 1);
  EXPECT_NEAR(boxMesh(V(0, 0, 0), V(1, 2, 3)).volume(), 6, 1e-12);  // outward
}

TEST(MeshTopology, FindsHolesPinchesAndFlips) {
  HullMesh open = boxMesh(V(0, 0, 0), V(1, 1, 1));
  open.triangles.pop_back();
  EXPECT_TRUE(meshTopology(open).manifold);
  EXPECT_FALSE(meshTopology(open).closed);

  // Two boxes sharing one corner vertex: every edge is fine, the vertex is not.
  HullMesh pinched = boxMesh(V(0, 0, 0), V(1, 1, 1));
  const HullMesh other = boxMesh(V(1, 1, 1), V(2, 2, 2));
  for (int i = 1; i < 8; ++i) pinched.vertices.push_back(other.vertices[std::size_t(i)]);
  for (auto t : other.triangles) {
    for (int& c : t) c = c == 0 ? 7 : c + 7;
    pinched.triangles.push_back(t);
  }
  EXPECT_FALSE(meshTopology(pinched).closed);

  HullMesh flipped = boxMesh(V(0, 0, 0), V(1, 1, 1));
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  EXPECT_FALSE(meshTopology(flipped).manifold);
}

TEST(ClipToBox, CutsTheSolidAndClosesIt) {
  const HullMesh clipped = clipToBox(boxMesh(V(0, 0, 0), V(2, 2, 2)), V(1, 1, 1), V(3, 3, 3));
  const MeshTopology t = meshTopology(clipped);
  EXPECT_TRUE(t.closed);
  EXPECT_NEAR(clipped.volume(), 1.0, 1e-9);
  EXPECT_TRUE(clipped.boxMin().isApprox(V(1, 1, 1)));
  EXPECT_TRUE(clipped.boxMax().isApprox(V(2, 2, 2)));
}

TEST(ClipToBox, KeepsWhatIsInsideAndDropsWhatIsOutside) {
  const HullMesh inside = boxMesh(V(1, 1, 1), V(2, 2, 2));
  const HullMesh kept = clipToBox(inside, V(0, 0, 0), V(3, 3, 3));
  EXPECT_EQ(kept.vertices, inside.vertices);
  EXPECT_EQ(kept.triangles, inside.triangles);
  EXPECT_TRUE(clipToBox(inside, V(4, 4, 4), V(5, 5, 5)).triangles.empty());
}

TEST(ClipToBox, RefusesAnOpenMesh) {
  HullMesh open = boxMesh(V(0, 0, 0), V(2, 2, 2));
  open.triangles.pop_back();
  EXPECT_THROW(clipToBox(open, V(1, 1, 1), V(3, 3, 3)), std::runtime_error);
}

}  // namespace
}  // namespace solidtex
