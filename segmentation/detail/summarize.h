#pragma once
#include <vector>

#include "segmentation/ExemplarStats.h"

namespace solidtex::detail {

// Particles that count for the statistics: the non-border ones, or all of them when every
// particle touches the border (a photo of a few large grains), rather than no statistics at all.
std::vector<const Particle2D*> statisticalParticles(const std::vector<Particle2D>& particles);

// The paper's 10-bin area histogram: equal-width bins between the smallest and largest area.
AreaHistogram buildAreaHistogram(const std::vector<const Particle2D*>& particles);

// Distinct (width, height) box sizes with their counts, sorted by (width, height).
std::vector<SizePair> buildSizePairs(const std::vector<const Particle2D*>& particles);

} // namespace solidtex::detail
