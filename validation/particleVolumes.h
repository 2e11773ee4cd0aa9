#pragma once
#include <cstdint>
#include <vector>

#include "common/Grid.h"

namespace solidtex {

/// The volumes, in voxels, of the particles of an id grid (0 background, 1..P), as a sample of the
/// solid's particle-volume distribution. With `cutByFaces` the volume is a block cut out of a larger
/// solid: particles touching a face are partial and left out, and each whole one stands for
/// 1 / (the number of places its box fits in the volume) particles (the Miles-Lantuejoul
/// correction), as large particles are cut more often; the weighted distribution is returned as
/// equally weighted quantiles, one per whole particle.
std::vector<double> particleVolumes(const Dims& dims, const std::vector<std::int32_t>& ids, bool cutByFaces);

}  // namespace solidtex
