#pragma once
#include <array>

#include "particles/HullMesh.h"

namespace solidtex {

/// One placed particle's surface.
struct ParticleMesh {
  int id = 0;                    ///< as in the particle_id grid
  std::array<float, 3> color{};  ///< linear RGB in [0,1]
  HullMesh surface;  ///< closed, outward, in the .vdb's index space (voxel (i,j,k) centred at (i,j,k))
};

}  // namespace solidtex
