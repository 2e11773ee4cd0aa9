#include "particleSolid/synthesizeMatrix.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "segmentation/textureExemplars.h"
#include "synthesis/synthesizeSolid.h"

namespace solidtex {
namespace {

// An exemplar grown into a periodic block by Chen and Wang's synthesis at the solid's scale.
std::optional<TiledMatrix> growBlock(cv::Mat exemplar, const std::string& name,
                                     const MatrixSynthesisOptions& options) {
  if (exemplar.empty()) return std::nullopt;
  if (options.voxelsPerPixel != 1) {
    const int side = std::max(1, int(std::lround(exemplar.cols * options.voxelsPerPixel)));
    cv::resize(exemplar, exemplar, {side, side}, 0, 0, cv::INTER_AREA);
  }
  SynthesisOptions synthesis;
  synthesis.size = options.size;
  synthesis.seed = options.seed;
  synthesis.threads = options.threads;
  synthesis.exemplarName = name;
  // The coarsest level's exemplar and volume must hold its neighbourhood: fewer levels when small.
  const auto tooSmall = [&] {
    const int coarsest = synthesis.levels - 1, n = synthesis.neighborhoods.front();
    return (exemplar.cols >> coarsest) < 2 * n || (options.size >> coarsest) < n ||
           options.size % (1 << coarsest) != 0;
  };
  while (synthesis.levels > 1 && tooSmall())
    synthesis.neighborhoods.erase(synthesis.neighborhoods.begin()), --synthesis.levels;
  if (exemplar.cols < 2 * synthesis.neighborhoods.front()) return std::nullopt;
  SynthesisResult result = synthesizeSolid(exemplar, synthesis);
  return TiledMatrix{result.volume.dims, std::move(result.volume.color)};
}

}  // namespace

std::optional<TiledMatrix> synthesizeMatrix(const ExemplarStats& stats,
                                            const MatrixSynthesisOptions& options) {
  return growBlock(matrixExemplar(stats), stats.name, options);
}

std::optional<TiledMatrix> synthesizeParticleGrain(const ExemplarStats& stats,
                                                   const MatrixSynthesisOptions& options) {
  return growBlock(particleExemplar(stats), stats.name, options);
}

}  // namespace solidtex
