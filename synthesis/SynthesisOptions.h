#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "common/Progress.h"

namespace solidtex {

/// Which continuous solid synthesis method runs.
enum class Method {
  ChenWang,  ///< Chen & Wang 2010: discrete solver, k-coherence, position and index histogram matching
  Kopf,      ///< Kopf et al. 2007: IRLS weighted average, colour histogram matching (baseline)
  Skeletal,  ///< Pan et al.: chen-wang on the exemplar's Haar skeleton, finer levels rebuilt from the
             ///< detail coefficients of the copied pixels
};

/// "chen-wang", "kopf" or "skeletal".
std::string methodName(Method method);
/// Parses "chen-wang" / "kopf" / "skeletal"; throws InputError otherwise.
Method parseMethod(const std::string& name);

/// What neighbourhood distances compare: colours (Pan et al.'s eq. 2) or the Haar coefficients of
/// every pixel's 2x2 block (eq. 3; NeighborhoodShape::wavelet).
enum class NeighborhoodDistance { Rgb, Wavelet };

/// "rgb" or "wavelet".
std::string distanceName(NeighborhoodDistance distance);
/// Parses "rgb" / "wavelet"; throws InputError otherwise.
NeighborhoodDistance parseDistance(const std::string& name);

/// How chen-wang's k-coherence similarity sets find each exemplar neighbourhood's nearest others.
enum class SimilaritySearch {
  Automatic,    ///< exact below SynthesisOptions::approximateFrom neighbourhoods, approximate from there
  Exact,        ///< kd-tree: exact; 40 s for a 512^2 photo, over 25 minutes for a 1024^2 one
  Approximate,  ///< FAISS inverted file (InvertedFileIndex): seconds, may miss a few nearest
};

/// "auto", "exact" or "approximate".
std::string similaritySearchName(SimilaritySearch search);
/// Parses "auto" / "exact" / "approximate"; throws InputError otherwise.
SimilaritySearch parseSimilaritySearch(const std::string& name);

/// Kopf et al.'s r (Chen and Wang's gamma): the slice energy sums ||s - e||^r (eq. 1), which the
/// IRLS weights ||s - e||^(r-2) minimise.
inline constexpr double kEnergyExponent = 0.8;

/// How chen-wang's discrete solver picks the exemplar pixel a voxel copies among the proposals.
enum class ProposalChoice {
  NearestToAverage,  ///< the proposal nearest to their weighted average (Han et al., as the paper says)
  LargestVote,       ///< the pixel with the largest summed weight, so re-weighting acts on the choice
  ColorMode,         ///< the proposal whose colour gathers the largest weight in a Gaussian colour kernel
};

/// Options of synthesizeSolid; defaults follow the paper and the `solidtex synthesize` command.
struct SynthesisOptions {
  Method method = Method::ChenWang;
  int size = 64;   ///< output is size^3 voxels; size / 2^(levels-1) must be whole
  int levels = 3;  ///< multi-resolution levels, coarsest first
  /// skeletal: how many of the finest levels are rebuilt from Haar details instead of optimised
  /// (the paper uses 1); fewer than `levels`
  int waveletLevels = 1;
  NeighborhoodDistance distance = NeighborhoodDistance::Rgb;
  std::vector<int> neighborhoods{
      8, 6, 4};        ///< neighbourhood side per level, coarsest first (one value: all levels)
  int k = 5;           ///< k-coherence similarity set size
  int iterations = 5;  ///< search + optimisation iterations per level
  int pcaDims = 20;    ///< PCA dimensions of neighbourhood vectors
  SimilaritySearch similaritySearch = SimilaritySearch::Automatic;
  std::optional<cv::Mat> control;  ///< greyscale map the exemplar's size: theta(p), phi(p) (brighter = more)
  std::uint64_t seed = 1;
  int threads = 0;           ///< worker threads; 0 = all cores. Output does not depend on it.
  std::string exemplarName;  ///< stored in the volume's metadata
  Progress progress;         ///< after every level and iteration, when set

  // Finer controls (rarely changed).
  int sparseStep = 2;       ///< slice neighbourhoods are matched on every step-th voxel in-plane
  int coherenceRadius = 1;  ///< k-coherence candidates come from slice neighbours within this radius
  int minSeparation = 2;    ///< similarity sets skip neighbourhoods within this many pixels
  /// SimilaritySearch::Automatic: levels with at least this many exemplar neighbourhoods (a 128^2
  /// exemplar has fewer) build their similarity sets approximately.
  int approximateFrom = 16384;
  /// A level is searched exhaustively when it has fewer exemplar neighbourhoods than this and
  /// centres x neighbourhoods (candidate distances per iteration) is at most exhaustiveBudget;
  /// otherwise by k-coherence. Exhaustive search matters at the coarsest level, where a random
  /// volume gives k-coherence nothing to build on; at finer levels k-coherence finds as good
  /// matches for a tenth of the time.
  int exhaustiveBelow = 2048;
  double exhaustiveBudget = 128e6;
  double irlsExponent = kEnergyExponent;  ///< r of the IRLS weights ||s - e||^(r-2)
  /// Eq. 4's counts H and theta are scaled as if theta (voxels per exemplar pixel) were this, so the
  /// re-weighting is equally strong at every level and size; <= 0 = the paper's plain counts.
  double histogramReferenceCount = 512;
  double indexReferenceCount = 128;  ///< the same for eq. 6 (slice neighbourhoods per exemplar neighbourhood)
  ProposalChoice choice = ProposalChoice::ColorMode;
  double modeBandwidth = 0.01;  ///< ColorMode kernel: exp(-||a - b||^2 / bandwidth), sRGB units
  int histogramBins = 16;       ///< per channel, Kopf's colour histograms (eq. 3)
  /// chen-wang re-weights with eq. 3 (colour histograms) besides eq. 4: without it a minority
  /// colour class erodes (two-colour discs: 0.10 instead of 0.30), see DiscreteHistograms.
  bool colorHistogramMatching = true;
};

}  // namespace solidtex
