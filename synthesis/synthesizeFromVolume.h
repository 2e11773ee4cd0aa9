#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/Box.h"
#include "common/DenseVolume.h"
#include "common/Progress.h"
#include "synthesis/FrameField.h"

namespace solidtex {

/// Options of synthesizeFromVolume; defaults follow Su 2008 (chapter 5) and `solidtex synthesize`.
struct VolumeSynthesisOptions {
  Dims dims{64, 64, 64};      ///< output voxels per axis
  std::optional<Box> region;  ///< only this box of the output, identical to it in the full volume
  /// Levels corrected against the exemplar, finest first; 0 = every level whose appearance window
  /// (window x spacing) fits in half the exemplar. Coarser levels are upsampled and jittered only.
  int levels = 0;
  double jitter = 0.7;  ///< r: each level's coordinates move by up to r x spacing per axis
  int k = 3;            ///< similarity set size
  int exclusion = 7;    ///< similarity set members keep out of each other's exclusion^3 cube
  int window = 5;       ///< appearance vectors: window^3 neighbourhoods (thesis: 5)
  int pcaDims = 16;     ///< appearance space dimensions
  int corrections = 4;  ///< correction passes per level, each in 8 subpasses (2x2x2 parity classes)
  const FrameField* field = nullptr;  ///< anisometric control over `dims`; null = isometric
  /// The output is a 3D torus: neighbourhoods wrap at its faces, so copies of it tile seamlessly.
  /// Every side must be a multiple of 2^(corrected levels). A field is read where the wrap lands.
  bool periodic = false;
  std::uint64_t seed = 1;
  int threads = 0;  ///< worker threads; 0 = all cores. Output does not depend on it.
  /// When set: before each analysed level, then after each correction pass and uncorrected level,
  /// with the share of the analysis or of the synthesis done.
  Progress progress;
};

/// Voxels beyond a box's faces that synthesising the box corrects at each corrected level: a
/// corrected voxel reads voxels up to 2 away in each of a pass's 8 subpasses, so a wrong value at a
/// window's edge travels at most this far inwards during a level.
constexpr int correctionMargin(int corrections) { return corrections * 8 * 2; }

/// What the analysis of an exemplar works on: every corrected level keeps appearance vectors and
/// similarity sets for each voxel of the domain.
struct VolumeAnalysisSize {
  double domainVoxels = 0;  ///< the exemplar less its border (0: too small to analyse)
  int levels = 0;           ///< corrected levels
};

/// The analysis size of an exemplar of `exemplar` voxels under `options`, without analysing it.
VolumeAnalysisSize volumeAnalysisSize(const Dims& exemplar, const VolumeSynthesisOptions& options);

/// One pyramid level, coarsest first.
struct VolumeLevelStatistics {
  int spacing = 1;   ///< exemplar voxels per output voxel step (h_l)
  Dims synthesised;  ///< voxels synthesised at this level (what the region needs, or all)
  bool corrected = false;
  int appearanceDims = 0;
  double keptVariance = 0;
  /// Share of exemplar voxels whose similarity set could not keep its members out of each other's
  /// exclusion cubes (too few similar voxels elsewhere among the nearest searched)
  double similarityFallbackShare = 0;
  double analysisSeconds = 0;  ///< appearance vectors and similarity sets
  double seconds = 0;          ///< upsampling, jitter and correction
};

/// What the synthesis did and how long it took.
struct VolumeSynthesisStatistics {
  std::array<int, 3> domain{};  ///< exemplar voxels usable as sources (the border dropped)
  std::vector<VolumeLevelStatistics> levels;
  double analysisSeconds = 0;
  double seconds = 0;
};

/// The synthesised box and the exemplar coordinate each voxel copies.
struct VolumeSynthesisResult {
  Box box;                                   ///< the region, or the whole output
  DenseVolume values;                        ///< the exemplar's channels, box.dims()
  std::vector<std::array<float, 3>> source;  ///< exemplar voxel copied, per voxel
  VolumeSynthesisStatistics statistics;
};

/// A volume exemplar analysed once (appearance vectors and similarity sets of every corrected
/// level) for one output: any box of it can then be synthesised, and equals that box of the whole
/// volume, so the bricks of a large volume share one analysis. `options.region` is not used.
class VolumeSynthesizer {
public:
  /// Checks the options and analyses the exemplar; throws InputError or OptionError with one line.
  VolumeSynthesizer(const DenseVolume& exemplar, const VolumeSynthesisOptions& options);
  ~VolumeSynthesizer();
  VolumeSynthesizer(VolumeSynthesizer&&) noexcept;
  VolumeSynthesizer& operator=(VolumeSynthesizer&&) noexcept;

  /// The box of the output (inside its dims); its statistics include the analysis.
  VolumeSynthesisResult synthesize(const Box& box) const;
  /// Output voxels the synthesis of `box` works on at the finest level (the box and its margin).
  std::size_t finestWindowVoxels(const Box& box) const;

private:
  struct Analysis;
  std::unique_ptr<Analysis> analysis_;
};

/// Su 2008 solid synthesis from a volume exemplar: appearance-space pyramid synthesis on exemplar
/// coordinates (Lefebvre and Hoppe 2005/2006 in 3D), steered by an optional frame field.
/// Same exemplar, options and seed give the same volume for any thread count, and a region equals
/// the same box of the full volume. Throws InputError with one line for bad input.
VolumeSynthesisResult synthesizeFromVolume(const DenseVolume& exemplar,
                                           const VolumeSynthesisOptions& options);

}  // namespace solidtex
