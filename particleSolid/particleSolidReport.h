#pragma once
/// @file particleSolidReport.h
/// @brief A particle solid's report: what was asked, what the photo showed, what was placed.
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "particleSolid/makeParticleSolid.h"

namespace solidtex {

/// The report of `solid`, made with `options`: the options that decide it, the photo's statistics,
/// the placement's figures, the textures, smoothing and sizing fits. Timings, memory and outputs are
/// the caller's to add.
nlohmann::json particleSolidReport(const ParticleSolid& solid, const ParticleSolidOptions& options);

/// The .vdb metadata of `solid`: version, `commandLine` (how it was asked for), seed, exemplar,
/// volume fraction, scale and the options that decide it.
std::map<std::string, std::string> particleSolidMetadata(const ParticleSolid& solid,
                                                         const ParticleSolidOptions& options,
                                                         const std::string& commandLine);

}  // namespace solidtex
