#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "validation/particleTruth.h"

namespace solidtex {

/// `solidtex truth`: a test photo with a known 3D truth behind it.
struct TruthJob {
  ParticleTruthOptions truth;
  std::string folder;  ///< receives photo.png, photo_xz.png, photo_yz.png, truth.vdb and truth.json
};

/// Makes the truth, writes photo.png (its middle xy section), photo_xz.png and photo_yz.png (the
/// other two middle sections, z down), truth.vdb and truth.json (the summary returned here: the
/// shape and options, particles per class, volume fraction, each photo's area fraction, every
/// particle's volume) into the folder.
nlohmann::json runTruth(const TruthJob& job);

}  // namespace solidtex
