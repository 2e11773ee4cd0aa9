#pragma once
/// @file
/// The matrix between a particle solid's particles, synthesised from the photo's own matrix.

#include <cstdint>
#include <optional>

#include "segmentation/ExemplarStats.h"
#include "voxel/paintParticleSolid.h"

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

}  // namespace solidtex
