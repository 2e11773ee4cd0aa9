#pragma once
/// @file phaseComparison.h
/// @brief A particle solid's phases, each against the photo's particles of that phase.
#include <string>

#include <nlohmann/json.hpp>

#include "common/SolidVolume.h"
#include "segmentation/ExemplarStats.h"
#include "validation/sectionStatistics.h"

namespace solidtex {

/// For a solid with phases (SolidVolume::particlePhase and the `phase_lab` colours and
/// `phase_grain` of its .vdb, named `volumePath` in errors): the photo's particles sorted by the
/// nearest of those phase centres and,
/// phase by phase, the photo's particles against the sections of the solid's particles of the
/// phase: area and volume fractions, section areas (KS, W1 / mean), shapes (compareSections). Null
/// for a solid of one phase. `stats` is the photo's, `scale` voxels per photo pixel, `options` the
/// sections' (minArea and window side already set), `diameter` the nearest-neighbour unit.
nlohmann::json phaseComparison(const ExemplarStats& stats, const SolidVolume& volume,
                               const std::string& volumePath, double scale, const SectionOptions& options,
                               double diameter);

}  // namespace solidtex
