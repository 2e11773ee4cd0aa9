#pragma once
/// @file brickSeams.h
/// @brief Whether a solid made brick by brick shows its bricks: the particles near the bricks' inner
/// faces against those elsewhere.
#include <cstdint>
#include <vector>

#include "common/Grid.h"

namespace solidtex {

struct BrickSeams {
  int facePlanes = 0;           ///< axis planes within `depth` of an inner brick face
  int otherPlanes = 0;          ///< the other axis planes
  double faceFraction = 0;      ///< particle area fraction of the face planes
  double otherFraction = 0;     ///< of the other planes
  double faceWindowSpread = 0;  ///< standard deviation of the face planes' window fractions
  double otherWindowSpread = 0;
};

/// Compares the axis planes of a particle id volume (x fastest, particles > 0) that lie within
/// `depth` planes of an inner face of bricks of `brickEdge` (bricksOf's) with the other planes: their
/// area fractions and the spread of the fractions of their `windowSide`-square windows. A seam shows
/// as a face fraction or spread apart from the rest's.
BrickSeams brickSeams(const std::vector<std::int32_t>& ids, const Dims& dims, int brickEdge, int depth,
                      int windowSide);

}  // namespace solidtex
