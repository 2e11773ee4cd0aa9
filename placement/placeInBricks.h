#pragma once
/// @file placeInBricks.h
/// @brief Particle placement brick by brick, each brick with its neighbours' particles as obstacles.
#include <functional>
#include <string>
#include <vector>

#include "common/Box.h"
#include "placement/SpaciousnessField.h"
#include "placement/placeLargestFirst.h"

namespace solidtex {

/// The processes that share the bricks. Each places the bricks of a colour dealt to it (the i-th of
/// the colour to process i mod size), and every process receives every brick's particles before
/// the next colour: each ends with the whole placement, the same for any number of processes.
struct BrickTeam {
  int rank = 0;
  int size = 1;
  /// Every process's bytes in rank order, on every process (Communicator::allGather); unused alone.
  std::function<std::vector<std::string>(std::string)> allGather;
};

struct BrickedPlacementOptions {
  /// The whole volume's placement: its dims, counted box (the bricks tile it), seed and sizes. Its
  /// progress is called after each brick. No particle limit. Periodic: each side an even number of
  /// bricks.
  PlacementOptions placement;
  PlacerKind placer = PlacerKind::Edt;
  float radiusCap = 1;  ///< the fields' cap: how far a particle reaches from its spot
  int brickEdge = 64;   ///< at least brickHalo(radiusCap) twice
  BrickTeam team;
};

/// How one brick went.
struct BrickPlacement {
  Box brick;  ///< in the counted box's coordinates
  int colour = 0;
  int rank = 0;               ///< the process that placed it
  int particles = 0;          ///< placed from spots in this brick, all rounds
  double volumeFraction = 0;  ///< of the brick, its neighbours' particles included
  double seconds = 0;
  std::string stopReason;  ///< of its last round
};

struct BrickedPlacementResult {
  PlacementResult placement;           ///< as placeLargestFirst's over the whole volume
  int halo = 0;                        ///< voxels each brick sees of its neighbours'
  std::vector<BrickPlacement> bricks;  ///< in bricksOf's order
  std::vector<double>
      colourSeconds;               ///< per colour, the wall time of its bricks and their exchange, all rounds
  int rounds = 0;                  ///< bins whose first pass went through every brick, and the rest
  std::size_t bytesExchanged = 0;  ///< every process's bricks as sent to the others, all colours
};

/// How far past its brick a brick's placement reaches (and sees): the radius cap, rounded up.
int brickHalo(float radiusCap);

/// Places particles into bricks of the counted box (bricksOf's), coloured by the parity of their
/// position so that bricks of one colour are a brick apart: the eight colours go one after the
/// other, the bricks of a colour in parallel. Each brick places by placeLargestFirst from spots of
/// its own (bricks on the counted box's faces also from the margin beyond), in a window of a halo
/// around it, with the particles of bricks done before as obstacles; its particles may reach into
/// the halo. Every brick has its own seed, so the result is the same at any thread count.
/// In a periodic volume, windows and particles wrap around its faces. Throws InputError when the
/// bricks are narrower than two halos, or do not cut a periodic volume's sides into even numbers.
BrickedPlacementResult placeInBricks(const ExemplarStats& stats, const ParticleFactory& factory,
                                     const BrickedPlacementOptions& options);

}  // namespace solidtex
