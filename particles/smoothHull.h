#pragma once
/// @file
/// Rounding a visual hull's sharp edges, where the prisms of its views meet.

#include "particles/HullMesh.h"

namespace solidtex {

/// How far a hull is rounded.
struct HullSmoothing {
  double radius =
      0.12;  ///< Gaussian sigma as a share of the hull's largest side; 0: none (the paper's sharp hulls)
  int resolution = 40;  ///< voxels across the hull's largest side while it is filtered
};

/// The hull voxelized, its inside indicator Gaussian-filtered (OpenCV, separable in 3D) and meshed
/// again at one half (OpenVDB volumeToMesh): edges and corners rounded over about `radius`, flat and
/// gently curved parts kept. Closed and outward oriented, in the hull's own coordinates. Returns
/// the hull itself when sigma (radius x resolution) is under half a voxel.
HullMesh smoothHull(const HullMesh& hull, const HullSmoothing& smoothing);

}  // namespace solidtex
