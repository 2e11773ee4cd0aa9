#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/Grid.h"
#include "particles/ParticleFactory.h"
#include "placement/SpaciousnessField.h"
#include "placement/placeLargestFirst.h"
#include "placement/sectionSizing.h"
#include "segmentation/analyzeExemplar.h"
#include "voxel/writeVolumeExports.h"

namespace solidtex {

/// What the volume's faces are to its particles.
enum class Boundary {
  Open,      ///< the volume is cut from a larger solid: particles run through its faces
  Walls,     ///< the paper's: particles stay inside, and thin out along every face
  Periodic,  ///< a 3D torus: particles leaving by a face come back by the opposite one, so copies tile
};

/// "open" | "walls" | "periodic"; throws InputError otherwise.
Boundary parseBoundary(const std::string& name);
const char* boundaryName(Boundary boundary);

/// How a part of the solid (the matrix between the particles, the particles' insides) is textured.
enum class Texture {
  Synthesized,  ///< a periodic solid texture grown from the photo's own (chen-wang), tiled
  Projected,    ///< the paper's: the photo's residual projected along one direction
};

/// "synthesized" | "projected" for `option` (named in the error); throws OptionError otherwise.
Texture parseTexture(const std::string& option, const std::string& name);
const char* textureName(Texture texture);

/// `solidtex particles`: photo to particle solid (.vdb, report, previews).
struct ParticleSolidJob {
  std::string photo;
  std::string output;  ///< .vdb path
  SegmentationOptions segmentation;
  Dims dims{128, 128, 128};
  double voxelsPerPixel =
      0;  ///< <= 0: 1, or less when the largest particle would exceed a quarter of the volume
  PlacerKind placer = PlacerKind::Edt;
  Sizing sizing = Sizing::Sections;
  Arrangement arrangement = Arrangement::Uniform;
  Boundary boundary = Boundary::Open;
  Texture matrix = Texture::Synthesized;
  Texture particleTexture = Texture::Projected;  ///< the particles' insides
  ParticleOptions particles;        ///< its seed is replaced by `seed`, its smoothing by `smoothing`
  std::optional<double> smoothing;  ///< HullSmoothing::radius; none: fitted to the photo's particle shapes
  std::uint64_t seed = 1;
  std::optional<std::string> report;
  std::optional<std::string> preview;  ///< folder for PNGs
  VolumeExports exports;               ///< TIFF stacks, numpy arrays, .vti
  std::optional<std::string> meshes;   ///< particle surfaces: .ply or .obj (writeParticleMeshes)
  std::string commandLine;             ///< stored in the .vdb's metadata
  bool progress = true;
};

/// The largest edge a volume may have; beyond it memory, not patience, runs out.
constexpr int kMaxVolumeEdge = 2048;

/// The largest side of the photo's particle boxes, pixels.
int largestBoxSide(const ExemplarStats& stats);

/// Voxels per photo pixel when none is asked for: 1, or less when the largest particle would exceed a
/// quarter of the volume's smallest edge.
double defaultVoxelsPerPixel(const ExemplarStats& stats, const Dims& dims);

/// The spaciousness cap for placing the photo's particles (the paper's sqrt(3) D / 2, plus a voxel).
float placementRadiusCap(const ExemplarStats& stats, double voxelsPerPixel);

/// The margin an open boundary places particles in around the volume: the radius of the largest
/// particle, so that the faces of the placement's volume leave the volume's own faces unaffected.
int openBoundaryMargin(const ExemplarStats& stats, double particleScale);

/// Runs the job, writes the requested files and returns the report.
nlohmann::json runParticleSolid(const ParticleSolidJob& job);

}  // namespace solidtex
