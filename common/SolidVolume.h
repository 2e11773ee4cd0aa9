#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "common/Grid.h"

namespace solidtex {

using Rgb = std::array<float, 3>;

/// A solid texture in dense working form, x fastest (Dims::index). Written to .vdb (docs/exports.md) as
/// `density` (FloatGrid, fog), `color` and `Cd` (Vec3SGrid, linear RGB, active over the whole box;
/// left out when empty, as for a solid made from a density volume), `particle_id` (Int32Grid),
/// `source_position` and `source` (Vec3SGrid) when present.
struct SolidVolume {
  Dims dims;
  std::vector<float> density;            ///< dims.count(); empty: 1 on particles, or everywhere without them
  std::vector<Rgb> color;                ///< dims.count(), linear RGB in [0,1]
  std::vector<std::int32_t> particleId;  ///< dims.count() or empty; 0 background, 1..P particles
  std::vector<std::array<float, 2>>
      sourcePosition;  ///< dims.count() or empty; exemplar pixel (x, y) each voxel copies
  std::vector<std::array<float, 3>> sourceVoxel;  ///< dims.count() or empty; exemplar voxel each voxel copies
  Voxel origin;  ///< where voxel (0,0,0) lies in a larger volume this is a region of (world = (origin + i) x
                 ///< voxel size)
  std::uint64_t activeVoxels = 0;  ///< read from a file: active voxels of its density or color grid
  std::map<std::string, std::string> metadata;  ///< file metadata: command line, seed, exemplar, ...
};

}  // namespace solidtex
