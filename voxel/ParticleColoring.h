#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
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

/// The colours of a placed particle solid (paper 3.6): each particle voxel gets its source particle's mean
/// colour plus that particle's own residual, each background voxel the background mean plus the
/// background residual. Residuals are laid into 3D by parallel projection along an oblique
/// direction (random per particle), so no axis slice shows them smeared into streaks.
/// The background's residual is laid at `voxelsPerPixel`, each particle's at the scale it was made at.
/// Particle id i is particles[i - 1], 0 the background.
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
///
/// Each voxel's colour depends only on the voxel and its particle id, so a volume keeps this rather
/// than its colours (12 bytes a voxel): writeVdb paints them leaf by leaf, paintColor all at once.
class ParticleColoring final : public VolumeColoring {
public:
  ParticleColoring(const ExemplarStats& stats, Dims dims, std::vector<ParticlePaint> particles,
                   double voxelsPerPixel, std::uint64_t seed, bool periodic = false,
                   std::optional<TiledMatrix> matrix = {}, std::optional<TiledMatrix> grain = {});
  ~ParticleColoring() override;
  Rgb at(int x, int y, int z, std::int32_t id) const override;

private:
  struct State;
  std::unique_ptr<const State> state_;
};

}  // namespace solidtex
