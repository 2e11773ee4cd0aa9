#pragma once
// Internal: testing a particle shape at a candidate spot, voxel by voxel.
#include <cstdint>
#include <vector>

#include "common/Grid.h"
#include "particles/VoxelShape.h"
#include "placement/detail/VoxelBits.h"

namespace solidtex::placement::detail {

/// A shape ready to be tried at spots: the spot takes its anchor voxel.
struct FitShape {
  Dims dims;
  Voxel anchor;               ///< local voxel put on the spot (the shape voxel nearest the box centre)
  std::vector<Voxel> voxels;  ///< local voxels, farthest from the anchor first
  std::vector<std::int32_t> squared;  ///< their squared distances to the anchor, non-increasing
  float innerRadius = 0;  ///< a spot needs at least this spaciousness: the nearest non-shape voxel
  float outerRadius = 0;  ///< a spot with this spaciousness always fits: just beyond the farthest voxel
  HullPose pose;          ///< the shape's hull, rotation and scaling
};

/// Prepares a non-empty shape; O(box) time.
FitShape prepareShape(const VoxelShape& shape);

/// The volume voxel of the shape's local (0,0,0) when its anchor sits on spot.
inline Voxel originAt(const FitShape& shape, const Voxel& spot) {
  return {spot.x - shape.anchor.x, spot.y - shape.anchor.y, spot.z - shape.anchor.z};
}

/// Whether the shape with its anchor on spot lies inside the volume and covers no occupied voxel;
/// in a periodic volume, whether its voxels' images cover none, each once (the shape is no wider
/// than the volume). `spaciousness` is a lower bound of the spot's distance to the nearest occupied
/// voxel: shape voxels nearer than that are known to be free and are not looked at.
bool fitsAt(const FitShape& shape, const Voxel& spot, float spaciousness, const VoxelBits& occupied,
            Dims dims, bool periodic);

}  // namespace solidtex::placement::detail
