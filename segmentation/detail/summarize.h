#pragma once
#include <vector>

#include "segmentation/ExemplarStats.h"

namespace solidtex::segmentation::detail {

// The paper's 10-bin area histogram: equal-width bins between the smallest and largest area.
AreaHistogram buildAreaHistogram(const std::vector<const Particle2D*>& particles);

// Distinct (width, height) box sizes with their counts, sorted by (width, height).
std::vector<SizePair> buildSizePairs(const std::vector<const Particle2D*>& particles);

}  // namespace solidtex::segmentation::detail
