#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "common/Grid.h"

namespace solidtex {

/// How a voxel shape was made from a hull (see voxelize): what rebuilds its surface where it lies.
struct HullPose {
  int hull = -1;  ///< index into ParticleFactory::hulls(); -1: not made from a hull
  /// The shape's local coordinates (voxel (i,j,k) is the cube from (i,j,k)) of a hull point p:
  /// linear * p + offset, where linear turns, then scales per axis.
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

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
