#pragma once
#include "particles/HullMesh.h"

namespace solidtex {

/// What a triangle mesh is, as CGAL's Polygon Mesh Processing finds it.
struct MeshTopology {
  bool manifold = false;  ///< every edge in two triangles wound opposite ways, every vertex one fan
  bool closed = false;    ///< manifold, with no border edge
  int components = 0;     ///< connected pieces (when manifold)
};

/// Checks a triangle soup (vertex indices in range) for the properties above.
MeshTopology meshTopology(const HullMesh& mesh);

}  // namespace solidtex
