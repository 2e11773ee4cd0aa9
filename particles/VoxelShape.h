#pragma once
#include <cstdint>
#include <vector>

#include "common/Grid.h"
#include "particles/HullPose.h"

namespace solidtex {

/// A particle as voxels in its own local box: inside[dims.index(i,j,k)] != 0 for the particle's voxels.
/// The box is tight (every face of the box touches the particle).
struct VoxelShape {
  Dims dims;
  std::vector<std::uint8_t> inside;
  HullPose pose;
  std::size_t voxelCount() const;
  /// Voxels of the particle with a 6-neighbour outside it (or on the box's faces).
  std::vector<Voxel> boundary() const;
};

}  // namespace solidtex
