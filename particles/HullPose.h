#pragma once
#include <Eigen/Core>

namespace solidtex {

/// How a voxel shape was made from a hull (see voxelize): what rebuilds its surface where it lies.
struct HullPose {
  int hull = -1;  ///< index into ParticleFactory::hulls(); -1: not made from a hull
  /// The shape's local coordinates (voxel (i,j,k) is the cube from (i,j,k)) of a hull point p:
  /// linear * p + offset, where linear turns, then scales per axis.
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

}  // namespace solidtex
