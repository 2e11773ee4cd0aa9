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
  /// Moves each box's middle side this share of the way to its longest side (> 0: disc-like
  /// bodies) or, negative, to its shortest (rod-like); 0 keeps the boxes the paper draws (3.5).
  double bodyForm = 0;
  std::uint64_t seed = 1;
};

/// A 3D box size picked the paper's hierarchical way (3.5), in photo pixels.
struct ParticleSize {
  int width = 0, height = 0, depth = 0;
  int source = -1;  ///< index into ExemplarStats::particles whose colour and residual it takes (3.6)
};

/// The photos of the other two planes of an anisotropic material, beside the xy photo a factory
/// takes (x across, y down): xz (x across, z down) and yz (y across, z down), at the same pixel size.
struct PlanePhotos {
  const ExemplarStats* xz = nullptr;
  const ExemplarStats* yz = nullptr;
  bool aligned() const { return xz != nullptr && yz != nullptr; }
};

/// Makes 3D particles from the photo's contours: visual hulls (3.4), sizes (3.5).
class ParticleFactory {
public:
  /// Builds the pool of unit hulls, in parallel and deterministically for the seed (identical at any
  /// thread count). Contours of particles cut by the photo's border are used only when there are no
  /// others. Keeps a reference to `stats` and to `planes`' statistics. With both other planes'
  /// photos the particles are aligned: each hull is carved by one contour of each plane's photo,
  /// seen along that plane's normal (three views whatever `views` says), and never turned. Throws
  /// InputError for options out of range or a photo whose contours carve no hull.
  ParticleFactory(const ExemplarStats& stats, const ParticleOptions& options, PlanePhotos planes = {});

  /// Depth for a (width, height) pair: drawn by frequency from the other side of every pair sharing
  /// width or height with it (paper 3.5); `source` is a particle whose box is (width, height).
  /// A pair equal to (width, height) offers both its values, each with half its count. Sizes that no
  /// pair shares a value with draw from all sides of all pairs; `source` is then the non-border
  /// particle with the nearest box (|dw| + |dh|), random among equals. Of several phases, the
  /// source is drawn first, among `phase`'s particles (any phase's when it is negative), and the
  /// depth from its phase's pairs alone. Aligned, width is x and
  /// height y, and the depth (z) is the height of the xz photo's boxes as wide as x and of the yz
  /// photo's as wide as y, by frequency (any of their heights when none is). The box's middle
  /// side then moves as ParticleOptions::bodyForm says (not when aligned).
  ParticleSize pickDepth(int width, int height, Rng& rng, int phase = -1) const;

  /// A particle from a random pool hull under a random rotation (none when aligned), non-uniformly scaled to
  /// the box (width, height, depth) voxels (each >= 1) and voxelized; one 6-connected piece in its tight box,
  /// which loses the face layers no voxel centre reached (see voxelize), with its pose. Thread-safe.
  /// Throws std::invalid_argument for a side outside [1, kMaxParticleSide].
  /// Of several phases (ExemplarStats::phaseCentres), the hull is one carved from `phase`'s contours
  /// (any, when the pool holds fewer hulls than phases).
  VoxelShape make(int width, int height, int depth, Rng& rng, int phase = 0) const;

  /// Each phase's size factor, where the phases' sections unfold to different factors: its
  /// particles are made at this many times the scale of the others (placement's makeScaled asks
  /// phaseScale); one value per phase, all 1 at first.
  void setPhaseScales(std::vector<double> scales);
  /// The phase's size factor (1 until setPhaseScales).
  double phaseScale(int phase) const;
  /// The largest phase's size factor: the largest particles' scale.
  double largestPhaseScale() const;

  /// The phase of a photo particle (ParticleSize::source); 0 for none.
  int phaseOf(int source) const;

  /// The same pool of hulls smoothed otherwise (from the sharp visual hulls), the first `maxHulls`
  /// of them when positive; the CGAL work is not redone.
  ParticleFactory withSmoothing(const HullSmoothing& smoothing, int maxHulls = 0) const;

  /// The same hulls with ParticleOptions::bodyForm `form`.
  ParticleFactory withBodyForm(double form) const;

  const std::vector<HullMesh>& hulls() const { return hulls_; }
  const ParticleOptions& options() const { return options_; }
  /// Made from three planes' photos: its particles keep the volume's axes, and the xy photo's
  /// particles are their sections across z.
  bool aligned() const { return planes_.aligned(); }

private:
  ParticleFactory(const ExemplarStats& stats, const ParticleOptions& options, PlanePhotos planes,
                  std::vector<HullMesh> sharpHulls);

  const ExemplarStats& stats_;
  PlanePhotos planes_;
  ParticleOptions options_;
  std::vector<HullMesh> sharpHulls_;               ///< the visual hulls (paper 3.4)
  std::vector<HullMesh> hulls_;                    ///< sharpHulls_ smoothed as the options say
  std::vector<std::vector<SizePair>> phasePairs_;  ///< each phase's box sizes (one: the photo's)
  std::vector<double> phaseScales_;                ///< empty: 1 for every phase
};

}  // namespace solidtex
