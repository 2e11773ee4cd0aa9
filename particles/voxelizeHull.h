#pragma once
#include <Eigen/Core>

#include "particles/HullMesh.h"
#include "particles/VoxelShape.h"

namespace solidtex {

/// Largest box side `voxelize` accepts (its exact integer arithmetic is sized for it).
inline constexpr int kMaxParticleSide = 8192;

/// The hull turned by `rotation`, scaled per axis so that its tight box is exactly
/// [0,w] x [0,h] x [0,d], as voxels: voxel (i,j,k) is inside when its centre (i+.5, j+.5, k+.5)
/// is (winding number > 0, exact predicates on a 2^-16 voxel grid). The result is one
/// 6-connected piece (the largest, when sampling splits thin parts off) in its tight box: (w,h,d)
/// less the face layers that no voxel centre reached (a sharp tip or edge touching a face between
/// centres), rather than a sliver grown to reach them. Thread-safe.
/// Throws std::invalid_argument for a side outside [1, kMaxParticleSide] or a flat or empty hull.
VoxelShape voxelize(const HullMesh& hull, const Eigen::Matrix3d& rotation, int w, int h, int d);

/// The hull as `voxelize` put it into the shape `pose` describes: turned, scaled and shifted into the
/// shape's local coordinates, where voxel (i,j,k) is the cube [i,i+1] x [j,j+1] x [k,k+1]. Its inside
/// voxel centres are the shape's voxels, plus any thin piece voxelize dropped.
HullMesh posedHull(const HullMesh& hull, const HullPose& pose);

}  // namespace solidtex
