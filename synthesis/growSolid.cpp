#include "synthesis/growSolid.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "common/bricksOf.h"
#include "common/secondsSince.h"

namespace solidtex {
namespace {

DenseVolume colorExemplar(const SolidVolume& solid) {
  DenseVolume exemplar{solid.dims, 3, std::vector<float>(solid.color.size() * 3)};
  for (std::size_t i = 0; i < solid.color.size(); ++i)
    std::copy_n(solid.color[i].data(), 3, &exemplar.values[3 * i]);
  return exemplar;
}

void copyBrick(const VolumeSynthesisResult& brick, SolidVolume& volume) {
  const Box& box = brick.box;
  const Dims d = box.dims();
  tbb::parallel_for(0, d.z, [&](int k) {
    for (int j = 0; j < d.y; ++j)
      for (int i = 0; i < d.x; ++i) {
        const float* c = brick.values.at(i, j, k);
        volume.color[volume.dims.index(box.lo.x + i, box.lo.y + j, box.lo.z + k)] = {c[0], c[1], c[2]};
      }
  });
}

}  // namespace

GrowResult growSolid(const cv::Mat& photoSrgb, const GrowOptions& o) {
  GrowResult result;
  SynthesisOptions seedOptions = o.seed;
  seedOptions.seed = o.volume.seed;
  seedOptions.threads = o.volume.threads;
  if (o.progress)
    seedOptions.progress = [&](const std::string& step, double fraction) {
      o.progress("seed solid: " + step, fraction);
    };
  SynthesisResult seed = synthesizeSolid(photoSrgb, seedOptions);
  result.seed = seed.statistics;

  const std::vector<Box> bricks = bricksOf(o.volume.dims, o.brickEdge);
  // Before the first brick, the analysis reports; then each brick's share of the growth is its
  // finest window's share (thinner last bricks, margins cut at the volume's faces).
  std::optional<std::size_t> current;
  std::vector<std::uint64_t> windowsBefore(bricks.size() + 1, 0);
  VolumeSynthesisOptions volumeOptions = o.volume;
  volumeOptions.region.reset();
  if (o.progress)
    volumeOptions.progress = [&](const std::string& step, double fraction) {
      if (!current) return o.progress("growing: " + step, fraction);
      o.progress("brick " + std::to_string(*current + 1) + "/" + std::to_string(bricks.size()) + ", " + step,
                 (double(windowsBefore[*current]) +
                  fraction * double(windowsBefore[*current + 1] - windowsBefore[*current])) /
                     double(windowsBefore.back()));
    };
  const VolumeSynthesizer synthesizer(colorExemplar(seed.volume), volumeOptions);
  seed = {};
  for (std::size_t b = 0; b < bricks.size(); ++b)
    windowsBefore[b + 1] = windowsBefore[b] + synthesizer.finestWindowVoxels(bricks[b]);

  result.volume.dims = o.volume.dims;
  result.volume.color.resize(o.volume.dims.count());
  result.volume.metadata["method"] = "grown from " + methodName(o.seed.method);
  const auto start = std::chrono::steady_clock::now();
  for (current = 0; *current < bricks.size(); ++*current) {
    const VolumeSynthesisResult brick = synthesizer.synthesize(bricks[*current]);
    copyBrick(brick, result.volume);
    result.analysisSeconds = brick.statistics.analysisSeconds;
    result.seedDomain = brick.statistics.domain;
  }
  result.growthSeconds = secondsSince(start);
  result.finestVoxels = windowsBefore.back();
  result.bricks = bricks.size();
  return result;
}

}  // namespace solidtex
