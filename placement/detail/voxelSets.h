#pragma once
// Internal helpers shared by the spaciousness fields: voxel sets, boxes, wall distances.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "common/Box.h"
#include "common/Grid.h"

namespace solidtex::placement::detail {

/// Linear voxel index; fields accept volumes of fewer than 2^32 voxels.
using VoxelIndex = std::uint32_t;

/// Throws InputError unless dims are positive and fit VoxelIndex, and maxRadius is positive and finite.
void checkFieldArguments(Dims dims, float maxRadius);

/// Throws std::out_of_range when a voxel lies outside dims.
void checkInside(Dims dims, const std::vector<Voxel>& voxels);
void checkInside(Dims dims, const Voxel& v);

/// Tight box of a non-empty voxel set.
Box boundingBox(const std::vector<Voxel>& voxels);

/// The shifts by whole volumes (a multiple of dims on each axis) that bring `box`, grown by `reach`
/// on every side, to overlap the volume: where a set of voxels in a periodic volume has images
/// that voxels of the volume can see within `reach`.
std::vector<Voxel> periodicShifts(Dims dims, const Box& box, int reach);

/// The voxels moved by `shift`.
std::vector<Voxel> shifted(const std::vector<Voxel>& voxels, const Voxel& shift);

/// Voxels of the set with a 6-neighbour outside it. For any voxel outside the set, the nearest
/// voxel of the set in any metric that grows with each coordinate difference (Euclidean,
/// Chebyshev) can be taken from these: the axis path from a nearest set voxel towards the outside
/// voxel leaves the set through a boundary voxel that is no farther.
std::vector<Voxel> boundaryVoxels(const std::vector<Voxel>& voxels);

/// Distance from voxel (i,j,k) to the nearest wall layer (index -1 or n on any axis): the
/// Euclidean and the 26-neighbour step distance agree here.
inline int wallDistance(Dims dims, int i, int j, int k) {
  int d = std::min(i + 1, dims.x - i);
  d = std::min(d, std::min(j + 1, dims.y - j));
  return std::min(d, std::min(k + 1, dims.z - k));
}

/// Squared Euclidean distance between voxel centres.
inline std::int64_t squaredDistance(const Voxel& a, const Voxel& b) {
  const std::int64_t dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
  return dx * dx + dy * dy + dz * dz;
}

}  // namespace solidtex::placement::detail
