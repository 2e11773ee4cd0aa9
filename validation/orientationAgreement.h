#pragma once
#include <cstddef>
#include <functional>

#include <Eigen/Core>

#include "common/DenseVolume.h"

namespace solidtex {

/// How orientationAgreement measures the local orientation.
struct OrientationOptions {
  double gradientSigma = 1.0;  ///< Gaussian derivative scale, voxels (0: central differences)
  double tensorSigma = 2.0;    ///< smoothing of the structure tensor, voxels (0: none)
  double minCoherence = 0.5;   ///< voxels with a less clear orientation are not counted
  /// Voxels within `margin` of a face are not counted; negative: ceil(2 (gradientSigma + tensorSigma)),
  /// 6 by default, where clamp-to-edge no longer matters.
  int margin = -1;
};

/// How well the volume's dominant gradient orientation follows the expected directions.
struct OrientationAgreement {
  double meanAbsCos = 0;          ///< mean |cos| over the counted voxels; 0 if none
  std::size_t voxelsCounted = 0;  ///< coherent voxels away from the border
  std::size_t voxelsTotal = 0;    ///< voxels away from the border (with a non-zero expected direction)
};

/// The dominant gradient orientation of `volume` (eigenvector of the largest eigenvalue of the smoothed
/// 3D structure tensor, per voxel) against an expected direction per voxel (any length, sign ignored);
/// mean |cos| over voxels whose orientation is clear (coherence (l1 - l2) / (l1 + l2) >= minCoherence,
/// away from the border). Multi-channel volumes sum the channels' structure tensors. Gaussian
/// derivatives and smoothing are separable, clamp-to-edge; the result does not depend on the number of
/// threads. `expectedDirection(i, j, k)` is called concurrently from several threads. A random
/// orientation scores 0.5 on average. Throws std::invalid_argument for a volume whose values do not
/// match its size or a negative sigma.
OrientationAgreement orientationAgreement(
    const DenseVolume& volume, const std::function<Eigen::Vector3f(int, int, int)>& expectedDirection,
    const OrientationOptions& options = {});

}  // namespace solidtex
