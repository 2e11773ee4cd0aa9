#pragma once
#include <string>

#include "validation/PhaseField.h"

namespace solidtex {

/// How tortuosityFactor solves for the steady concentration.
struct TortuosityOptions {
  double tolerance = 1e-6;  ///< relative residual at which conjugate gradients stop
  int maxIterations = 0;    ///< <= 0: ten times the longest side plus 1000
};

/// Steady diffusion through a phase along one axis, as TauFactor defines it: concentration 1 and 0
/// held half a voxel beyond the field's two faces across `axis`, unit diffusivity within the phase,
/// none outside it and across the other faces.
struct Tortuosity {
  int axis = 0;
  double fraction = 0;              ///< phi, of the whole phase
  double effectiveDiffusivity = 0;  ///< D_eff / D_bulk
  double factor = 0;                ///< tau = phi D_bulk / D_eff
  double connectedFraction = 0;     ///< share of the phase joined to both faces
  int iterations = 0;
  double residual = 0;      ///< relative residual reached
  double fluxMismatch = 0;  ///< |inflow - outflow| / inflow: how converged the flux is
  double seconds = 0;
};

/// The tortuosity factor of a phase along `axis` (0..2; 0..1 in an image), by conjugate gradients
/// (Eigen) preconditioned with aggregation multigrid on the face-neighbour graph of the phase's
/// voxels joined to both faces. Throws InputError
/// with one line when the phase does not join the two faces.
Tortuosity tortuosityFactor(const PhaseField& phase, int axis, const TortuosityOptions& options = {});

}  // namespace solidtex
