#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/Grid.h"

namespace solidtex {

using Rgb = std::array<float, 3>;

/// Colours painted on demand from the particle ids: a volume too large to hold its colours dense
/// (12 bytes a voxel) keeps this instead, and the .vdb writer paints each leaf as it writes it.
class VolumeColoring {
public:
  virtual ~VolumeColoring() = default;
  /// The linear RGB colour of voxel (x, y, z), whose particle id is `id`.
  virtual Rgb at(int x, int y, int z, std::int32_t id) const = 0;
};

/// A solid texture in dense working form, x fastest (Dims::index). Written to .vdb (docs/exports.md) as
/// `density` (FloatGrid, fog), `color` and `Cd` (Vec3SGrid, linear RGB, active over the whole box;
/// left out when there are none, as for a solid made from a density volume), `particle_id` (Int32Grid),
/// `phase` (Int32Grid), `source_position` and `source` (Vec3SGrid) when present.
struct SolidVolume {
  Dims dims;
  std::vector<float> density;  ///< dims.count(); empty: 1 on particles, or everywhere without them
  std::vector<Rgb> color;      ///< dims.count(), linear RGB in [0,1]; or empty, painted by `coloring`
  std::shared_ptr<const VolumeColoring> coloring;  ///< with particleId and no `color`: the colours
  std::vector<std::int32_t> particleId;            ///< dims.count() or empty; 0 background, 1..P particles
  /// Per particle id - 1: its phase, 0..K-1 (a material with several kinds of particle); empty: one.
  /// Written as the `phase` grid (Int32Grid: 0 matrix, 1..K the phases, on the particles' voxels).
  std::vector<std::uint8_t> particlePhase;
  std::vector<std::array<float, 2>>
      sourcePosition;  ///< dims.count() or empty; exemplar pixel (x, y) each voxel copies
  std::vector<std::array<float, 3>> sourceVoxel;  ///< dims.count() or empty; exemplar voxel each voxel copies
  Voxel origin;  ///< where voxel (0,0,0) lies in a larger volume this is a region of (world = (origin + i) x
                 ///< voxel size)
  std::uint64_t activeVoxels = 0;  ///< read from a file: active voxels of its density or color grid
  std::map<std::string, std::string> metadata;  ///< file metadata: command line, seed, exemplar, ...

  bool hasColor() const { return !color.empty() || coloring; }
  /// The colour of voxel (x, y, z), dense or painted.
  Rgb colorAt(int x, int y, int z) const {
    const std::size_t i = dims.index(x, y, z);
    return color.empty() ? coloring->at(x, y, z, particleId[i]) : color[i];
  }
};

/// Every voxel's phase from the particle ids and their phases: 0 matrix, 1..K (dims.count(), x
/// fastest); empty when the volume has one phase.
std::vector<std::uint8_t> phaseGrid(const SolidVolume& volume);

/// Paints a volume's `coloring` into its dense `color` (for exports and numpy arrays); nothing when
/// it is dense already.
void paintColor(SolidVolume& volume);

}  // namespace solidtex
