#pragma once
#include "common/ProgressLine.h"
#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// A warning line on stderr, below the progress line when there is one, when most of what stood
/// out in the photo (by area) was dropped as smaller than the minimum area: the solid would miss it.
void warnOfDroppedRegions(const ExemplarStats& stats, ProgressLine* progress = nullptr);

}  // namespace solidtex
