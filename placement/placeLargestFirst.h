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

/// A particle in the volume before placement starts: one a neighbouring brick placed.
struct PlacementObstacle {
  int bin = 0;                 ///< its area-histogram bin
  std::size_t voxelCount = 0;  ///< all its voxels, also those outside this volume
  std::vector<Voxel> voxels;   ///< those inside this volume
  bool own = false;  ///< with PlacementOptions::ownVoxels: one of this placement's own, placed before
};

/// Voxels a phase's particles are expected to take, per area bin: the pilot shapes placement makes
/// before it places (their count and the sum of their voxels).
struct PlacementPilot {
  std::array<int, 10> shapes{};
  std::array<double, 10> voxels{};
};

struct PlacementOptions {
  Dims dims{128, 128, 128};
  /// Where the area fraction is reached and counted, when the volume is a margin around the solid
  /// that will be cut out of it (particles then run through the solid's faces; cropToCountedBox);
  /// empty: everywhere. Only this box's ids are kept: outside it particles are obstacles.
  std::optional<Box> counted;
  /// The volume is a 3D torus: particles cross a face and continue on the opposite one (the field
  /// must be periodic too; no counted box).
  bool periodic = false;
  /// Where the spots particles are centred on may lie; empty: anywhere. A brick of a larger volume
  /// places into its own box, while its particles reach past it into its neighbours'.
  std::optional<Box> spots;
  /// Particles already there: they are obstacles from the start, and their voxels inside the
  /// counted box count toward its fraction, each by its share in its bin.
  std::vector<PlacementObstacle> obstacles;
  /// A brick's share of a larger placement: the voxels (inside the counted box) of the particles it
  /// places, and of its own obstacles, must reach the fraction of this many voxels; its neighbours'
  /// obstacles are theirs to count. None: the counted box's voxels, every obstacle counted.
  std::optional<std::size_t> ownVoxels;
  /// Ids over the whole volume, not only the counted box: a brick keeps the voxels its particles
  /// put into its neighbours'.
  bool idsEverywhere = false;
  /// Per bin, what is added to a bin's share of the particles before it is rounded down to its
  /// quota: 0.5 rounds to the nearest. A brick holds few particles of a bin, so bricks take values
  /// spread over [0, 1): each brick's count is then right on average, and their sum close to the
  /// whole volume's.
  std::array<double, 10> quotaDither{0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
  /// The phases' pilots (placementPilots); empty: made from `seed`. Bricks share one, so that they
  /// follow one schedule.
  std::vector<PlacementPilot> pilots;
  /// Only the first pass of the first phase over the bins from this one up, then stop: a round of a
  /// bricked placement, which goes bin by bin through every brick. None: the whole placement.
  std::optional<int> firstPassDownTo;
  /// Of each bin's quota, the share the first pass places (0.85); a bricked placement goes through a
  /// bin that holds much of the volume in several rounds of a part each.
  double firstPassShare = 0.85;
  double voxelsPerPixel = 1;  ///< photo pixels to voxels
  /// The volume fraction to fill; below 0: the photo's area fraction. Photos of three planes each
  /// estimate it: their mean is the better estimate.
  double volumeFraction = -1;
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
  bool periodic = false;  ///< the volume is a 3D torus; particles' voxels wrap around it
  Box counted;            ///< the box ids cover: PlacementOptions::counted, or the whole volume
  /// counted.dims().count() (with PlacementOptions::idsEverywhere: dims.count()), x fastest,
  /// 0 background, 1..P
  std::vector<std::int32_t> ids;
  std::vector<PlacedParticle> particles;
  std::array<int, 10> placedPerBin{};
  std::array<int, 10> rejectedPerBin{};      ///< (w,h) tries that found no spot
  double volumeFraction = 0;                 ///< of the counted box (ownVoxels: of those)
  std::array<double, 10> volumeHistogram{};  ///< ratios of placed particles per bin of volume (paper Fig. 10)
  std::string
      stopReason;       ///< "area fraction reached" | "particle limit reached" | "no bin fits any more ..."
  int shrinkSteps = 0;  ///< times the photo's sizes were shrunk to fill a crowded volume
  double smallestScale = 1;           ///< the last shrink's size factor
  int particlesBeforeShrinking = -1;  ///< particles placed before the first shrink; -1: none
};

/// The share of its particles each area bin gets in placeLargestFirst's first phase: the particle
/// weights' (or the photo's) frequencies of the bin's sizes.
std::array<double, 10> firstPhaseBinShares(const ExemplarStats& stats, const PlacementOptions& options);

/// The pilots placeLargestFirst makes for each phase it may go through, from options' sizes and seed.
std::vector<PlacementPilot> placementPilots(const ExemplarStats& stats, const ParticleFactory& factory,
                                            const PlacementOptions& options);

/// The volume fraction a placement fills: options.volumeFraction, or the photo's area fraction.
double targetFraction(const ExemplarStats& stats, const PlacementOptions& options);

/// Places particles one by one, largest area bin first, each at a spot of `field` that holds it
/// (paper 3.7-3.8), until every bin is done or the target fraction (targetFraction) is reached. When nothing
/// fits before that, the photo's sizes are tried again smaller (up to three times 0.85).
/// Particles never overlap and never cross the walls; in a periodic volume they cross the faces.
PlacementResult placeLargestFirst(const ExemplarStats& stats, const ParticleFactory& factory,
                                  SpaciousnessField& field, const PlacementOptions& options);

}  // namespace solidtex
