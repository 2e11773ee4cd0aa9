#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/writeVolumeExports.h"
#include "particleSolid/makeParticleSolid.h"

namespace solidtex {

/// `solidtex particles`: photo file to particle solid files (.vdb, report, previews, exports, meshes).
struct ParticleSolidJob : ParticleSolidOptions {
  std::string photo;  ///< the xy plane's when photoXz or photoYz is given
  /// A material that differs by direction: the photos of its xz and yz planes (z down); one given
  /// stands for both. Both the same as `photo`: the one-photo solid.
  std::optional<std::string> photoXz, photoYz;
  /// With photoXz or photoYz: the side of a pixel of the xy, xz and yz photos (one unit); the xz and
  /// yz photos are resampled to the xy photo's. Empty: one size for all, or with
  /// pixelSizesFromFiles the files' resolution metadata (planePixelSizes).
  std::vector<double> pixelSizes;
  bool pixelSizesFromFiles = false;
  std::string output;  ///< .vdb path
  std::optional<std::string> report;
  std::optional<std::string> preview;   ///< folder for PNGs
  VolumeExports exports;                ///< TIFF stacks, numpy arrays, .vti
  std::optional<std::string> meshPath;  ///< particle surfaces: .ply or .obj (writeParticleMeshes)
  std::string commandLine;              ///< stored in the .vdb's metadata
  bool progress = true;
};

/// Runs the job, writes the requested files and returns the report.
nlohmann::json runParticleSolid(const ParticleSolidJob& job);

}  // namespace solidtex
