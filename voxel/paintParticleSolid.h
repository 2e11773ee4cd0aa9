#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "common/SolidVolume.h"
#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// A placed particle as painting needs it.
struct ParticlePaint {
  int source = -1;                 ///< index into ExemplarStats::particles
  std::array<double, 3> centre{};  ///< centre of its box, in volume voxels
  double voxelsPerPixel = 1;       ///< the scale its shape was made at
};

/// A block of background colours that tiles seamlessly (a periodic solid texture of the photo's
/// matrix), laid over the whole volume by repeating it along every axis.
struct TiledMatrix {
  Dims dims;               ///< the block's size
  std::vector<Rgb> color;  ///< dims.count(), linear RGB in [0,1], x fastest
};

/// Colours a placed particle solid (paper 3.6): each particle voxel gets its source particle's mean
/// colour plus that particle's own residual, each background voxel the background mean plus the
/// background residual. Residuals are laid into 3D by parallel projection along an oblique
/// direction (random per particle), so no axis slice shows them smeared into streaks.
/// The background's residual is laid at `voxelsPerPixel`, each particle's at the scale it was made at.
/// `ids` (dims.count(), 0 background, id i is particles[i - 1]) becomes the volume's particle_id grid;
/// it is taken by value so that callers can move a 512^3 grid in rather than hold two copies.
/// density is left implicit (1 on particles, as writeVdb writes it).
/// A periodic volume (a 3D torus) is painted to tile: a particle's residual follows it across the
/// faces, and the background's is cross-faded near each face with its continuation from the
/// opposite one, its variance kept.
/// With a `matrix`, each background voxel takes the matrix's colour instead (tiled, so a volume
/// whose sides are multiples of the block's stays periodic): the background then has the photo's
/// matrix texture in every direction, where a projection draws streaks along its direction.
/// With a `grain` (a block of the particles' grain about its mean, synthesizeParticleGrain), only
/// the shading of a particle's residual is projected (splitResidual: smooth, it draws no stripes);
/// its grain is the block's deviation, laid at an offset of the particle's own and scaled to its
/// source's grain spread. Projected whole, the grain draws stripes across every slice but one.
SolidVolume paintParticleSolid(const ExemplarStats& stats, Dims dims, std::vector<std::int32_t> ids,
                               const std::vector<ParticlePaint>& particles, double voxelsPerPixel,
                               std::uint64_t seed, bool periodic = false, const TiledMatrix* matrix = nullptr,
                               const TiledMatrix* grain = nullptr);

}  // namespace solidtex
