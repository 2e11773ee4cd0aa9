#pragma once
#include <cstdint>

#include "validation/PhaseField.h"

namespace solidtex {

/// Connectivity of a phase's voxels (pixels in 2D) for the Euler characteristic: face neighbours
/// only (6 in 3D, 4 in 2D), or every neighbour that shares a vertex (26, 8), as scikit-image's
/// euler_number with connectivity 1 or 3 (2D: 1 or 2).
enum class Connectivity { Faces, Vertices };

/// The Euler characteristic of a phase in the given connectivity, the field padded with voxels
/// outside it: components - tunnels + cavities (2D: components - holes). Exact, by counting the
/// cells of the voxels' cubical complex (closed cubes for Vertices, open for Faces).
std::int64_t eulerCharacteristic(const PhaseField& phase, Connectivity connectivity);

/// The Minkowski functionals of a phase per unit volume (3D) or area (2D), in voxel units, for the
/// material the field samples: the field's faces are not the phase's boundary.
struct MinkowskiDensities {
  double fraction = 0;       ///< volume (area) fraction
  double boundary = 0;       ///< surface area per volume S_V (2D: perimeter per area L_A)
  double meanCurvature = 0;  ///< 3D: integral of the mean curvature (k1 + k2) / 2 per volume, M_V; 2D: 0
  double euler = 0;          ///< Euler characteristic (Vertices connectivity) per volume (area)
};

/// Boundary by Crofton's formula from the phase's entries and exits along lines in the 13 (2D: 4)
/// lattice directions, weighted by their share of the unit sphere (circle); M_V by Crofton's
/// formula from the Euler characteristic of the axis-plane sections, 2 pi times its mean density.
/// Densities count the 2x2x2 windows of voxels that lie in the field (or wrap around it when
/// `periodic`), so that they estimate a stationary material's without bias from the field's faces.
MinkowskiDensities minkowskiDensities(const PhaseField& phase, bool periodic = false);

}  // namespace solidtex
