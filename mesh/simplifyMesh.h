#pragma once
#include <cstddef>

#include "particles/HullMesh.h"

namespace solidtex {

/// The mesh with its edges collapsed, the least shape-changing first (CGAL, Garland-Heckbert plane
/// quadrics), no face turning over, until at most `triangles` are left or no collapse keeps the
/// surface a manifold. Closed and manifold meshes stay so. The mesh itself when it is not a
/// manifold surface or has no more than `triangles`.
HullMesh simplifyMesh(const HullMesh& mesh, std::size_t triangles);

}  // namespace solidtex
