#pragma once
/// @file makeParticleSolid.h
/// @brief Photo to particle solid in memory: segmentation, hulls, sizing, placement, painting.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "common/Grid.h"
#include "common/PhaseTimer.h"
#include "common/Progress.h"
#include "common/SolidVolume.h"
#include "mesh/ParticleMesh.h"
#include "particleSolid/synthesizeMatrix.h"
#include "particles/ParticleFactory.h"
#include "particles/fitBodyForm.h"
#include "particles/fitHullSmoothing.h"
#include "placement/SpaciousnessField.h"
#include "placement/placeInBricks.h"
#include "placement/placeLargestFirst.h"
#include "placement/sectionSizing.h"
#include "placement/wholeParticleVolumes.h"
#include "segmentation/analyzeExemplar.h"
#include "segmentation/particlePhases.h"

namespace solidtex {

/// What the volume's faces are to its particles.
enum class Boundary {
  Open,      ///< the volume is cut from a larger solid: particles run through its faces
  Walls,     ///< the paper's: particles stay inside, and thin out along every face
  Periodic,  ///< a 3D torus: particles leaving by a face come back by the opposite one, so copies tile
};

/// "open" | "walls" | "periodic"; throws OptionError otherwise.
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

/// Everything that decides a particle solid, apart from the photo.
struct ParticleSolidOptions {
  SegmentationOptions segmentation;
  /// Kinds of particle: each phase's particles take its own shapes, sizes and colours, and the
  /// solid gets a phase per particle (SolidVolume::particlePhase).
  PhaseOptions phases;
  Dims dims{128, 128, 128};
  double voxelsPerPixel =
      0;  ///< <= 0: 1, or less when the largest particle would exceed a quarter of the volume
  PlacerKind placer = PlacerKind::Edt;
  Sizing sizing = Sizing::Sections;
  Arrangement arrangement = Arrangement::Uniform;
  Boundary boundary = Boundary::Open;
  Texture matrix = Texture::Synthesized;
  Texture particleTexture = Texture::Projected;  ///< the particles' insides
  /// Its seed is replaced by `seed`, its smoothing by `smoothing`, its body form by `bodyForm`.
  ParticleOptions particles;
  std::optional<double> smoothing;  ///< HullSmoothing::radius; none: fitted to the photo's particle shapes
  std::optional<double> bodyForm = 0.0;  ///< ParticleOptions::bodyForm; none: fitted to the photo's sections
  std::uint64_t seed = 1;
  bool meshes = false;  ///< also mesh each particle's surface (ParticleSolid::meshes)
  /// The caller will paint every colour at once (exports, numpy arrays): the memory check counts it.
  bool denseColor = false;
  /// Place a smaller block first and time it, so that the progress gives placement's share done and
  /// its time left (up to a twentieth more placing; large volumes only, PlacementTimeline). The
  /// solid is the same either way.
  bool timePlacement = false;
  /// Place in bricks of this edge, one colour of bricks after another (placeInBricks); 0: the whole
  /// volume at once.
  int brickEdge = 0;
  /// With brickEdge: the processes that share the bricks. The solid is the same for any; each
  /// process places its bricks and ends with the whole placement.
  BrickTeam brickTeam;
};

/// How one texture of the solid was made: synthesized (a tiled block of `block` voxels) or projected,
/// with the reason when synthesis was asked for but not possible.
struct TextureChoice {
  Texture texture = Texture::Projected;
  int block = 0;
  std::string reason;
};

/// A particle solid and how it was made.
struct ParticleSolid {
  ExemplarStats stats;    ///< the photo's segmentation and particle statistics (the xy photo's)
  ParticlePhases phases;  ///< how its particles were sorted into phases; empty centres: one phase
  /// The xz and yz photos' statistics when the solid is made from three planes' photos; empty else.
  std::vector<ExemplarStats> planeStats;
  double voxelsPerPixel = 1;  ///< the photo's scale in the volume
  BodyFormFit bodyForm;
  SmoothingFit smoothing;
  SectionSizing sizing;
  /// Of several phases sized from their sections: each one's size factor (ParticleFactory's phase
  /// scales; `sizing` then holds factor 1 and every phase's weights).
  std::vector<double> phaseSizeFactors;
  PlacementResult placement;          ///< the placed particles; its ids are moved into `volume`
  WholeParticleVolumes wholeVolumes;  ///< the placed particles' 3D sizes, before the faces cut them
  /// With ParticleSolidOptions::brickEdge: the bricks, how each went, the colours' times. Its
  /// placement is moved into `placement`.
  std::optional<BrickedPlacementResult> bricks;
  SolidVolume volume;  ///< particle ids and linear RGB colours, dims.count() each
  TextureChoice matrix, particleTexture;
  std::vector<ParticleMesh> meshes;  ///< when asked for, in the volume's index space
  PhaseTimer timer;                  ///< the phases so far; callers may time their own after them
  double memoryEstimate = 0;  ///< bytes: the peak particleSolidPeakBytes expected, checked before placing
};

/// The volume fraction the solid fills: the photo's area fraction, or with the planes' photos the
/// mean of the three (each is one section and estimates it).
double targetVolumeFraction(const ParticleSolid& solid);

/// Refuses (OptionError) options out of range: the volume's edges, the scale, views and shapes.
void checkParticleSolidOptions(const ParticleSolidOptions& options);

/// Makes a particle solid in stages, so that a caller can act between them (report the photo's
/// statistics before the long work, place into one brick of a larger volume). Call the stages in
/// order; each throws InputError for a photo it cannot use, OptionError for options out of range.
class ParticleSolidBuilder {
public:
  /// Checks the options and that the volume fits in memory.
  explicit ParticleSolidBuilder(ParticleSolidOptions options, Progress progress = {});

  /// Segments the photo (CV_32FC3 sRGB in [0, 1], RGB order), measures its particles and sorts them
  /// into the phases the options ask for; `name` labels it in reports and messages.
  const ExemplarStats& analyze(const cv::Mat& photoSrgb, const std::string& name);
  /// For a material that differs by direction, after analyze (whose photo is then the xy plane's):
  /// segments the photos of the xz plane (x across, z down) and of the yz plane (y across, z down),
  /// at the xy photo's pixel size; the particles are then aligned (PlanePhotos). Both the xy photo
  /// itself: nothing, and the solid is the one-photo solid, byte for byte. Refuses (OptionError) a
  /// mask, which segments one photo, and phases, which sort one photo's particles.
  void analyzePlanes(const cv::Mat& xzSrgb, const std::string& xzName, const cv::Mat& yzSrgb,
                     const std::string& yzName);
  /// Builds the hull shapes and fits the smoothing and the section sizing.
  void makeParticles();
  /// Places particles until the photo's area fraction (three photos: their mean) is met or nothing more fits.
  const PlacementResult& place();
  /// Textures the matrix and the particles, paints the volume and meshes it when asked.
  ParticleSolid finish();

private:
  int largestSide() const;  // pixels: the largest particle box side of every photo
  void sizePhases(double scale);

  ParticleSolidOptions options_;
  Progress progress_;
  cv::Mat photo_;  // the xy photo, to know it again among the planes'
  ParticleSolid solid_;
  std::optional<ParticleFactory> factory_;
};

/// The one-off form of ParticleSolidBuilder: all stages in order.
ParticleSolid makeParticleSolid(const cv::Mat& photoSrgb, const std::string& name,
                                const ParticleSolidOptions& options, const Progress& progress = {});

/// Peak resident memory, in bytes, of making and writing a particle solid of `dims` whose particles are
/// placed in a block of `placed` voxels (larger by the open boundary's margin). Measured on gravel
/// from 96^3 to 512^3 (docs/performance.md): placing holds 7.6 bytes per placed voxel (the field's
/// keys and bucket entries, the occupancy bits) and the ids, 4 per voxel; writing 8.2 per voxel
/// (the ids while the colours are painted leaf by leaf, then the id and density grids), or 19 with
/// `denseColor` (the colours, their grid and an export's 8-bit copy beside the ids); every run 200 MiB.
/// The `delaunay` placer's triangulation adds 49 bytes per placed voxel.
double particleSolidPeakBytes(const Dims& dims, const Dims& placed, PlacerKind placer,
                              bool denseColor = false);

/// The largest edge a volume may have; beyond it memory, not patience, runs out.
constexpr int kMaxVolumeEdge = 2048;

/// The largest side of the photo's particle boxes, pixels.
int largestBoxSide(const ExemplarStats& stats);

/// Voxels per photo pixel when none is asked for: 1, or less when the largest particle (its
/// largest side in pixels) would exceed a quarter of the volume's smallest edge.
double defaultVoxelsPerPixel(int largestSide, const Dims& dims);

/// The spaciousness cap for placing particles whose largest side is `largestSide` pixels (the
/// paper's sqrt(3) D / 2, plus a voxel).
float placementRadiusCap(int largestSide, double voxelsPerPixel);

/// The margin an open boundary places particles in around the volume: the radius of the largest
/// particle, so that the faces of the placement's volume leave the volume's own faces unaffected.
int openBoundaryMargin(int largestSide, double particleScale);

}  // namespace solidtex
