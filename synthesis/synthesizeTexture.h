#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "synthesis/SynthesisOptions.h"

namespace solidtex {

/// Which 2D texture synthesis method runs.
enum class TextureMethod {
  Kwatra,    ///< Kwatra et al. 2005 texture optimisation: every level optimised (the baseline)
  Skeletal,  ///< Pan et al.: the optimisation on the exemplar's Haar skeleton, finer levels rebuilt
             ///< from the detail coefficients of the recorded sources (Algorithm 1)
};

/// "kwatra" or "skeletal".
std::string textureMethodName(TextureMethod method);
/// Parses "kwatra" / "skeletal"; throws InputError otherwise.
TextureMethod parseTextureMethod(const std::string& name);

/// Options of synthesizeTexture; defaults follow the `solidtex synthesize2d` command.
struct TextureSynthesisOptions {
  TextureMethod method = TextureMethod::Kwatra;
  int width = 128, height = 128;  ///< output size; each a multiple of 2^(levels-1) * sparseStep
  int levels = 3;                 ///< multi-resolution levels, coarsest first
  /// Side per level, coarsest first (one value: all levels). Empty: 8 at the finest level, 12 at the
  /// next, 16 above, each at most half the level's exemplar and at most its output (small exemplars
  /// still run).
  std::vector<int> neighborhoods;
  int iterations = 5;     ///< search + optimisation iterations per level
  int pcaDims = 20;       ///< PCA dimensions of neighbourhood vectors
  int waveletLevels = 1;  ///< skeletal: finest levels rebuilt instead of optimised
  NeighborhoodDistance distance = NeighborhoodDistance::Rgb;
  int sparseStep = 2;                     ///< neighbourhoods are matched on every step-th pixel
  double irlsExponent = kEnergyExponent;  ///< r of the IRLS weights ||x - z||^(r-2)
  std::uint64_t seed = 1;
  int threads = 0;    ///< worker threads; 0 = all cores. Output does not depend on it.
  Progress progress;  ///< after every level and iteration, when set
};

/// One optimised level.
struct TextureLevelStatistics {
  int width = 0, height = 0;  ///< output size at this level
  int exemplarWidth = 0, exemplarHeight = 0;
  int neighborhood = 0;
  double analysisSeconds = 0;    ///< neighbourhoods, PCA, k-d tree
  std::vector<double> energies;  ///< mean RMS distance of the matched neighbourhoods, per iteration
  double seconds = 0;
};

/// The synthesised texture and how it was made.
struct TextureSynthesisResult {
  cv::Mat image;                               ///< CV_32FC3 sRGB in [0,1], R,G,B order; tiles periodically
  std::vector<int> neighborhoods;              ///< per optimised level
  std::vector<TextureLevelStatistics> levels;  ///< the optimised levels
  std::optional<double> rebuildSeconds;        ///< skeletal
  double seconds = 0;
};

/// Synthesises a periodic 2D texture from an exemplar (CV_32FC3 sRGB, as loadPhoto returns).
/// Same exemplar, options and seed give the same image for any thread count. Throws InputError with
/// one line for bad input: an exemplar smaller than a level's neighbourhood, a size the levels and
/// step cannot reach, invalid counts.
TextureSynthesisResult synthesizeTexture(const cv::Mat& exemplar, const TextureSynthesisOptions& options);

}  // namespace solidtex
