#pragma once
#include "particles/HullMesh.h"

namespace solidtex {

/// The connected piece of a closed, outward mesh that encloses the most volume (the first on ties),
/// with its vertices renumbered; the mesh itself when it is one piece. A visual hull of non-convex
/// views may fall into pieces, of which voxelize keeps the largest.
HullMesh largestPiece(const HullMesh& mesh);

}  // namespace solidtex
