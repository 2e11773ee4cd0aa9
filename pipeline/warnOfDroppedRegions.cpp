#include "pipeline/warnOfDroppedRegions.h"

#include <cstdio>

namespace solidtex {

void warnOfDroppedRegions(const ExemplarStats& stats, ProgressLine* progress) {
  if (stats.areaShareBelowMinArea <= 0.5) return;
  if (progress) progress->done();
  std::fprintf(stderr,
               "solidtex: warning: %s: %d regions, %.0f%% of the area that stands out, are smaller than the "
               "minimum area of %g pixels and were dropped (see --min-area)\n",
               stats.name.c_str(), stats.regionsBelowMinArea, 100 * stats.areaShareBelowMinArea,
               stats.minArea);
}

}  // namespace solidtex
