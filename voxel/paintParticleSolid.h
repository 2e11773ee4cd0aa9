#pragma once
#include <cstdint>

#include "placement/placeLargestFirst.h"
#include "segmentation/ExemplarStats.h"
#include "voxel/SolidVolume.h"

namespace solidtex {

/// Colours a placed particle solid (paper 3.6): each particle voxel gets its source particle's mean
/// colour plus that particle's own residual, each background voxel the background mean plus the
/// background residual. Residuals are laid into 3D by parallel projection along an oblique
/// direction (random per particle), so no axis slice shows them smeared into streaks.
/// The background's residual is laid at `voxelsPerPixel`, each particle's at the scale it was made at.
/// density is left implicit (1 on particles, as writeVdb writes it); particle_id is the placement's id grid, moved out of `placement` (whose
/// ids are left empty) so that a 512^3 solid does not hold two copies.
SolidVolume paintParticleSolid(const ExemplarStats& stats, PlacementResult& placement, double voxelsPerPixel,
                               std::uint64_t seed);

} // namespace solidtex
