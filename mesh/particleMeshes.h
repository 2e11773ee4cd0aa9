#pragma once
/// @file
/// The surfaces of a particle solid's particles, where the placement put them.

#include <vector>

#include "mesh/ParticleMesh.h"
#include "particles/HullMesh.h"
#include "placement/placeLargestFirst.h"

namespace solidtex {

/// Each placed particle's hull (the largest piece of `hulls[pose.hull]`, the factory's pool, smoothed
/// when its shapes were) turned, scaled and moved as its voxels were, in the .vdb's index space, and cut to
/// the volume [-1/2, dims - 1/2] where it runs through a face; in a periodic volume it is left whole,
/// running past the face, and its copies moved by dims on each axis tile with it. The voxel centres inside a
/// mesh are the particle's voxels, but for thin parts that fell apart between voxel centres. Colours are left
/// black. In parallel; the same result at any thread count. Throws std::invalid_argument for a particle with
/// no pool hull.
std::vector<ParticleMesh> particleMeshes(const PlacementResult& placement,
                                         const std::vector<HullMesh>& hulls);

}  // namespace solidtex
