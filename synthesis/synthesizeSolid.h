#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "common/SolidVolume.h"
#include "synthesis/SynthesisOptions.h"

namespace solidtex {

/// One search and optimisation step of a level.
struct IterationStatistics {
  double energy = 0;  ///< mean distance of the slice neighbourhoods to their matches, before the step
  double searchSeconds = 0;
  double solveSeconds = 0;
  std::optional<double> positionCoverage;  ///< chen-wang: share of exemplar pixels copied after the step
};

/// How a level's slice neighbourhoods find their exemplar matches.
enum class NeighborhoodSearch { Exhaustive, KCoherence, KdTree };

/// "exhaustive", "k-coherence" or "kd-tree".
std::string searchName(NeighborhoodSearch search);

/// One level of the pyramid, coarsest first.
struct LevelStatistics {
  int volumeSize = 0;  ///< edge of the level's cubic volume
  int exemplarWidth = 0;
  int exemplarHeight = 0;
  int neighborhood = 0;           ///< side of the square neighbourhoods
  int exemplarNeighborhoods = 0;  ///< how many the exemplar has
  int pcaDims = 0;
  double pcaKeptVariance = 0;  ///< share of the neighbourhoods' variance the PCA keeps
  NeighborhoodSearch search = NeighborhoodSearch::Exhaustive;
  /// k-coherence with approximate similarity sets: the inverted file's cells and probes; 0 if exact
  int similarityLists = 0;
  int similarityProbes = 0;
  double analysisSeconds = 0;  ///< neighbourhoods, PCA, similarity sets or tree
  std::vector<IterationStatistics> iterations;
  double seconds = 0;
};

/// What the synthesis did and how long it took.
struct SynthesisStatistics {
  std::vector<int> neighborhoods;       ///< side per optimised level, coarsest first
  std::vector<LevelStatistics> levels;  ///< the optimised levels (skeletal: all but the rebuilt ones)
  /// chen-wang and skeletal: share of exemplar neighbourhoods matched at the finest optimised level
  std::optional<double> indexCoverage;
  std::optional<double> rebuildSeconds;  ///< skeletal: rebuilding the finer levels from Haar details
  double seconds = 0;
};

/// The synthesised volume and how it was made.
struct SynthesisResult {
  SolidVolume volume;  ///< dims size^3, linear RGB colour, density empty, sourcePosition for chen-wang
  SynthesisStatistics statistics;
};

/// Synthesises a solid texture from a 2D exemplar (CV_32FC3 sRGB in [0,1], R,G,B order, as
/// loadPhoto returns; 8-bit and grey images are accepted too) with the chosen method.
/// Same exemplar, options and seed give the same volume for any thread count.
/// Throws InputError with one line for bad input: an exemplar smaller than a level's neighbourhood,
/// a size the levels cannot reach, a control map of the wrong size, invalid counts.
SynthesisResult synthesizeSolid(const cv::Mat& exemplarSrgb, const SynthesisOptions& options);

/// Synthesises a material that differs by direction from one exemplar per plane (Kopf et al.'s and
/// Chen and Wang's three-exemplar form): exemplarByAxis[a] for the slices orthogonal to axis a, so
/// [0] the yz plane (y across, z down), [1] the xz plane (x across, z down), [2] the xy plane (x
/// across, y down). The three must be of one size; each is cut to the rows every level halves
/// exactly. Three equal exemplars give synthesizeSolid(exemplarByAxis[2], options)'s volume. The
/// volume records no source positions (they would point into three images). Throws InputError as
/// the one-exemplar form, and for exemplars of different sizes or a control map.
SynthesisResult synthesizeSolid(const std::array<cv::Mat, 3>& exemplarByAxis,
                                const SynthesisOptions& options);

}  // namespace solidtex
