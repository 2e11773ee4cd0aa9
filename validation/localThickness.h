#pragma once
#include <vector>

#include "validation/PhaseField.h"

namespace solidtex {

/// How localThickness samples sphere radii.
struct LocalThicknessOptions {
  int sizes =
      25;  ///< radii, log-spaced from the largest inscribed sphere's down to 1 voxel (PoreSpy's default)
  double largest = 0;  ///< > 0: log-space the radii from this one instead, so that fields compare
};

/// The radius of the largest sphere (disc) inside the phase: the greatest distance from a voxel of
/// it to the nearest voxel outside; 1 when the phase has no voxel outside.
double largestInscribedRadius(const PhaseField& phase);

/// The local thickness of a phase (Hildebrand & Rüegsegger): for every voxel, the radius of the
/// largest sphere inside the phase that covers it, among the radii sampled.
struct LocalThickness {
  std::vector<float> radius;       ///< per voxel, 0 outside the phase
  std::vector<double> sizes;       ///< the radii sampled, largest first, in voxels
  std::vector<double> cumulative;  ///< share of the phase's voxels whose thickness is at least sizes[i]
};

/// By porosimetry, as PoreSpy's local_thickness: for each radius r, largest first, the centres whose
/// distance to the nearest voxel outside the phase is at least r, dilated by r (one exact EDT each).
LocalThickness localThickness(const PhaseField& phase, const LocalThicknessOptions& options = {});

}  // namespace solidtex
