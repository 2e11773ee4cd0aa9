#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "common/Random.h"
#include "particles/HullMesh.h"
#include "particles/VoxelShape.h"
#include "particles/smoothHull.h"
#include "segmentation/ExemplarStats.h"

namespace solidtex {

struct ParticleOptions {
  int views = 3;             ///< contours per visual hull (paper: 3 to 5)
  int shapes = 64;           ///< distinct hulls built up front and reused with fresh sizes and rotations
  int contourVertices = 48;  ///< contours are simplified to about this many vertices before the CGAL work
  HullSmoothing smoothing;   ///< rounds the edges where the views' prisms meet
  std::uint64_t seed = 1;
};

/// A 3D box size picked the paper's hierarchical way (3.5), in photo pixels.
struct ParticleSize {
  int width = 0, height = 0, depth = 0;
  int source = -1;  ///< index into ExemplarStats::particles whose colour and residual it takes (3.6)
};

/// Makes 3D particles from the photo's contours: visual hulls (3.4), sizes (3.5).
class ParticleFactory {
public:
  /// Builds the pool of unit hulls, in parallel and deterministically for the seed (identical at any
  /// thread count). Contours of particles cut by the photo's border are used only when there are no
  /// others. Keeps a reference to `stats`. Throws InputError for options out of range or a photo
  /// whose contours carve no hull.
  ParticleFactory(const ExemplarStats& stats, const ParticleOptions& options);

  /// Depth for a (width, height) pair: drawn by frequency from the other side of every pair sharing
  /// width or height with it (paper 3.5); `source` is a particle whose box is (width, height).
  /// A pair equal to (width, height) offers both its values, each with half its count. Sizes that no
  /// pair shares a value with draw from all sides of all pairs; `source` is then the non-border
  /// particle with the nearest box (|dw| + |dh|), random among equals.
  ParticleSize pickDepth(int width, int height, Rng& rng) const;

  /// A particle from a random pool hull under a random rotation, non-uniformly scaled to the box
  /// (width, height, depth) voxels (each >= 1) and voxelized; one 6-connected piece in its tight box,
  /// which loses the face layers no voxel centre reached (see voxelize), with its pose. Thread-safe.
  /// Throws std::invalid_argument for a side outside [1, kMaxParticleSide].
  VoxelShape make(int width, int height, int depth, Rng& rng) const;

  /// The same pool of hulls smoothed otherwise (from the sharp visual hulls), the first `maxHulls`
  /// of them when positive; the CGAL work is not redone.
  ParticleFactory withSmoothing(const HullSmoothing& smoothing, int maxHulls = 0) const;

  const std::vector<HullMesh>& hulls() const { return hulls_; }
  const ParticleOptions& options() const { return options_; }

private:
  ParticleFactory(const ExemplarStats& stats, const ParticleOptions& options,
                  std::vector<HullMesh> sharpHulls);

  const ExemplarStats& stats_;
  ParticleOptions options_;
  std::vector<HullMesh> sharpHulls_;  ///< the visual hulls (paper 3.4)
  std::vector<HullMesh> hulls_;       ///< sharpHulls_ smoothed as the options say
};

}  // namespace solidtex
