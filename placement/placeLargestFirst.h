#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/Box.h"
#include "common/Grid.h"
#include "particles/ParticleFactory.h"
#include "placement/SpaciousnessField.h"
#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// Where each particle goes among the spots that hold it.
enum class Arrangement {
  BestFit,  ///< the tightest spot (paper 3.7): particles pack into clusters and leave open regions
  Uniform,  ///< a random spot, as random sequential addition scatters particles; best fit once none is found
};

/// "best-fit" | "uniform"; throws InputError otherwise.
Arrangement parseArrangement(const std::string& name);
const char* arrangementName(Arrangement arrangement);

struct PlacementOptions {
  Dims dims{128, 128, 128};
  /// Where the area fraction is reached and counted, when the volume is a margin around the solid
  /// that will be cut out of it (particles then run through the solid's faces; cropToCountedBox);
  /// empty: everywhere. Only this box's ids are kept: outside it particles are obstacles.
  std::optional<Box> counted;
  /// The volume is a 3D torus: particles cross a face and continue on the opposite one (the field
  /// must be periodic too; no counted box).
  bool periodic = false;
  double voxelsPerPixel = 1;  ///< photo pixels to voxels
  std::uint64_t seed = 1;
  int candidatesPerTry = 256;  ///< best-fit spots checked voxel by voxel before a (w,h) pair is rejected
  Arrangement arrangement = Arrangement::Uniform;
  int maxParticles = 0;  ///< stop after this many particles; 0: no limit
  /// Each photo particle's share of the 3D particles (per ExemplarStats::particles index); empty: the
  /// photo's frequencies (the paper's rule). When no bin of these shares fits any more before the
  /// area fraction is reached, the photo's frequencies fill the rest, at the photo's sizes.
  std::vector<double> particleWeights;
  double sizeFactor = 1;  ///< with particleWeights: their particles are this many times the photo's sizes
  /// Called now and then, while the field may be taking the last particle: it must not read the field. May be
  /// empty.
  std::function<void(double fraction, int placed)> progress;
  int progressEvery = 64;  ///< particles between progress calls
};

/// One particle in the volume.
struct PlacedParticle {
  int id = 0;       ///< 1..P, as in the id grid
  Voxel origin;     ///< the volume voxel of the shape's local (0,0,0); periodic: its image may lie outside
  Dims box;         ///< the shape's tight box, voxels
  int source = -1;  ///< index into ExemplarStats::particles (colour, residual)
  int bin = 0;      ///< area-histogram bin it was made for
  std::size_t voxelCount = 0;
  double voxelsPerPixel = 1;  ///< the scale it was made at: its photo particle's pixels to voxels
  HullPose pose;  ///< its hull, rotation and scaling: posedHull(hull, pose) + origin is its surface
};

struct PlacementResult {
  Dims dims;
  bool periodic = false;          ///< the volume is a 3D torus; particles' voxels wrap around it
  Box counted;                    ///< the box ids cover: PlacementOptions::counted, or the whole volume
  std::vector<std::int32_t> ids;  ///< counted.dims().count(), x fastest, 0 background, 1..P
  std::vector<PlacedParticle> particles;
  std::array<int, 10> placedPerBin{};
  std::array<int, 10> rejectedPerBin{};      ///< (w,h) tries that found no spot
  double volumeFraction = 0;                 ///< of the counted box
  std::array<double, 10> volumeHistogram{};  ///< ratios of placed particles per bin of volume (paper Fig. 10)
  std::string
      stopReason;       ///< "area fraction reached" | "particle limit reached" | "no bin fits any more ..."
  int shrinkSteps = 0;  ///< times the photo's sizes were shrunk to fill a crowded volume
  double smallestScale = 1;           ///< the last shrink's size factor
  int particlesBeforeShrinking = -1;  ///< particles placed before the first shrink; -1: none
};

/// Places particles one by one, largest area bin first, each at a spot of `field` that holds it
/// (paper 3.7-3.8), until every bin is done or the photo's area fraction is reached. When nothing
/// fits before that, the photo's sizes are tried again smaller (up to three times 0.85).
/// Particles never overlap and never cross the walls; in a periodic volume they cross the faces.
PlacementResult placeLargestFirst(const ExemplarStats& stats, const ParticleFactory& factory,
                                  SpaciousnessField& field, const PlacementOptions& options);

}  // namespace solidtex
