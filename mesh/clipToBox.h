#pragma once
#include <Eigen/Core>

#include "particles/HullMesh.h"

namespace solidtex {

/// The solid a closed, outward mesh bounds, cut to the box [lo, hi] (CGAL's corefinement with exact
/// constructions): closed and outward again, with new faces on the box's planes. A mesh inside the box
/// comes back unchanged; one outside it comes back empty. Throws std::runtime_error when the mesh is
/// not closed or intersects itself.
HullMesh clipToBox(const HullMesh& mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

}  // namespace solidtex
