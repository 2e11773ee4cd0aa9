#pragma once
/// @file
/// The textures of a particle solid synthesised from the photo's own: the matrix between the
/// particles and the grain inside them.

#include <cstdint>
#include <optional>

#include "segmentation/ExemplarStats.h"
#include "voxel/ParticleColoring.h"

namespace solidtex {

/// Options of synthesizeMatrix.
struct MatrixSynthesisOptions {
  int size = 64;              ///< edge of the periodic block; a multiple of 4
  double voxelsPerPixel = 1;  ///< the solid's scale: the exemplar is resampled to it first
  std::uint64_t seed = 1;
  int threads = 0;  ///< 0: all cores; the block does not depend on it
};

/// A periodic block of the photo's matrix: matrixExemplar (the window with the most matrix, its
/// particles filled from the matrix around them) grown into a solid by Chen and Wang's synthesis,
/// which tiles seamlessly. Empty when the photo shows too little matrix for an exemplar.
std::optional<TiledMatrix> synthesizeMatrix(const ExemplarStats& stats,
                                            const MatrixSynthesisOptions& options);

/// A periodic block of the particles' grain about a mid grey (linear 0.5), without their colours:
/// particleExemplar grown into a solid the same way, for painting the particles' insides with a
/// texture that has no direction. Empty when the photo shows too little particle for an exemplar.
std::optional<TiledMatrix> synthesizeParticleGrain(const ExemplarStats& stats,
                                                   const MatrixSynthesisOptions& options);

}  // namespace solidtex
