#include "synthesis/synthesizeTexture.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>
#include <sstream>

#include <tbb/parallel_for.h>

#include "common/Error.h"
#include "common/Random.h"
#include "common/ThreadLimit.h"
#include "common/interruption.h"
#include "common/secondsSince.h"
#include "synthesis/detail/ExemplarNeighborhoods.h"
#include "synthesis/detail/ExemplarPyramid.h"
#include "synthesis/detail/HaarPyramid.h"
#include "synthesis/detail/KdTree.h"

namespace solidtex {

using namespace synthesis::detail;

std::string textureMethodName(TextureMethod method) {
  return method == TextureMethod::Kwatra ? "kwatra" : "skeletal";
}

TextureMethod parseTextureMethod(const std::string& name) {
  if (name == "kwatra") return TextureMethod::Kwatra;
  if (name == "skeletal") return TextureMethod::Skeletal;
  throw OptionError("unknown texture synthesis method '" + name + "' (expected kwatra or skeletal)");
}

namespace {

using Clock = std::chrono::steady_clock;

/// The texture being optimised: periodic, with the exemplar pixel each pixel copies or mostly takes.
struct Texture {
  RgbImage rgb;
  std::vector<std::int32_t> source;

  int wrapX(int x) const { return ((x % rgb.width) + rgb.width) % rgb.width; }
  int wrapY(int y) const { return ((y % rgb.height) + rgb.height) % rgb.height; }
};

/// TextureSynthesisOptions::neighborhoods left empty: Kwatra's sizes shrunk to fit small exemplars.
std::vector<int> fittedNeighborhoods(const cv::Mat& exemplar, const TextureSynthesisOptions& o) {
  const int wavelet = o.distance == NeighborhoodDistance::Wavelet ? 1 : 0;  // one more pixel of extent
  std::vector<int> n(std::size_t(o.levels));
  for (int l = 0; l < o.levels; ++l) {
    const int shift = o.levels - 1 - l;
    const int wanted = shift == 0 ? 8 : shift == 1 ? 12 : 16;
    const int exemplarRoom = std::min(exemplar.cols >> shift, exemplar.rows >> shift) / 2 - wavelet;
    const int outputRoom = std::min(o.width >> shift, o.height >> shift);  // the output wraps around
    n[std::size_t(l)] = std::max(2, std::min({wanted, exemplarRoom, outputRoom}));
  }
  return n;
}

/// Neighbourhood side per level (one value broadcasts); checks everything the exemplar's size decides.
std::vector<int> validate(const cv::Mat& exemplar, const TextureSynthesisOptions& o) {
  if (exemplar.empty()) throw InputError("exemplar image is empty");
  if (o.levels < 1 || o.levels > 8) throw OptionError("--levels must be in [1, 8]");
  if (o.iterations < 1 || o.iterations > 100) throw OptionError("--iterations must be in [1, 100]");
  if (o.pcaDims < 1 || o.pcaDims > 512) throw OptionError("--pca-dims must be in [1, 512]");
  if (o.threads < 0 || o.sparseStep < 1) throw InputError("invalid thread count or step");
  if (o.width < 2 || o.height < 2 || o.width > 8192 || o.height > 8192)
    throw OptionError("--size must be within [2, 8192] on both sides");
  const int rebuilt = o.method == TextureMethod::Skeletal ? o.waveletLevels : 0;
  if (o.method == TextureMethod::Skeletal && (o.waveletLevels < 1 || o.waveletLevels >= o.levels))
    throw InputError(
        "--wavelet-levels must be at least 1 and below --levels: the coarsest level is optimised");
  std::vector<int> n = o.neighborhoods.empty() ? fittedNeighborhoods(exemplar, o) : o.neighborhoods;
  if (n.size() == 1) n.assign(std::size_t(o.levels), n[0]);
  if (int(n.size()) != o.levels)
    throw OptionError("--neighborhoods lists " + std::to_string(n.size()) + " sizes but --levels is " +
                      std::to_string(o.levels));
  const int multiple = (1 << (o.levels - 1)) * o.sparseStep;
  if (o.width % multiple != 0 || o.height % multiple != 0)
    throw OptionError("--size " + std::to_string(o.width) + " " + std::to_string(o.height) +
                      " must be a multiple of " + std::to_string(multiple) + " (2^(levels-1) x the step)");
  for (int l = 0; l < o.levels - rebuilt; ++l) {
    const int shift = o.levels - 1 - l;
    if (n[std::size_t(l)] < 2 || n[std::size_t(l)] > 32)
      throw OptionError("neighbourhood sides must be in [2, 32]");
    const int extent = n[std::size_t(l)] + (o.distance == NeighborhoodDistance::Wavelet ? 1 : 0);
    if ((exemplar.cols >> shift) < extent || (exemplar.rows >> shift) < extent)
      throw InputError("exemplar " + std::to_string(exemplar.cols) + "x" + std::to_string(exemplar.rows) +
                       " is too small for the " + std::to_string(n[std::size_t(l)]) +
                       "-pixel neighbourhood at level " + std::to_string(l + 1) + " (" +
                       std::to_string(exemplar.cols >> shift) + "x" + std::to_string(exemplar.rows >> shift) +
                       " there)");
    if ((o.width >> shift) < n[std::size_t(l)] || (o.height >> shift) < n[std::size_t(l)])
      throw OptionError("--size is too small for the neighbourhood at level " + std::to_string(l + 1));
  }
  n.resize(std::size_t(o.levels - rebuilt));
  return n;
}

Texture withColorsFromSources(Texture t, const RgbImage& exemplar) {
  t.rgb.data.resize(t.source.size() * 3);
  for (std::size_t i = 0; i < t.source.size(); ++i)
    std::copy_n(exemplar.data.data() + 3 * std::size_t(t.source[i]), 3, t.rgb.data.data() + 3 * i);
  return t;
}

/// Level 0: every pixel copies a random exemplar pixel from its own stream.
Texture randomTexture(int width, int height, const RgbImage& exemplar, std::uint64_t seed) {
  Texture t{{width, height, {}}, std::vector<std::int32_t>(std::size_t(width) * std::size_t(height))};
  for (std::size_t i = 0; i < t.source.size(); ++i) {
    Rng rng(deriveSeed(seed, i));
    t.source[i] = std::int32_t(uniformIndex(rng, std::uint64_t(exemplar.pixelCount())));
  }
  return withColorsFromSources(std::move(t), exemplar);
}

/// The next finer level: child (2x + a, 2y + b) copies pixel 2p + (a, b) of the finer exemplar, p its
/// parent's source.
Texture upsample(const Texture& coarse, int coarseExemplarWidth, const RgbImage& exemplar) {
  Texture t{{2 * coarse.rgb.width, 2 * coarse.rgb.height, {}}, {}};
  t.source.resize(std::size_t(t.rgb.width) * std::size_t(t.rgb.height));
  for (int y = 0; y < t.rgb.height; ++y)
    for (int x = 0; x < t.rgb.width; ++x) {
      const std::int32_t p = coarse.source[std::size_t(y / 2) * coarse.rgb.width + x / 2];
      const int sx = std::min(2 * (p % coarseExemplarWidth) + x % 2, exemplar.width - 1);
      const int sy = std::min(2 * (p / coarseExemplarWidth) + y % 2, exemplar.height - 1);
      t.source[std::size_t(y) * t.rgb.width + x] = sy * exemplar.width + sx;
    }
  return withColorsFromSources(std::move(t), exemplar);
}

/// The best exemplar neighbourhood for every centre of the sparse grid, and its squared distance.
struct Matches {
  int step = 2, cols = 0, rows = 0;
  std::vector<std::int32_t> match;
  std::vector<float> distance;
};

Matches search(const Texture& t, const ExemplarNeighborhoods& en, const KdTree& tree, int step) {
  Matches m{step, t.rgb.width / step, t.rgb.height / step, {}, {}};
  m.match.resize(std::size_t(m.cols) * std::size_t(m.rows));
  m.distance.resize(m.match.size());
  const NeighborhoodShape& shape = en.shape;
  tbb::parallel_for(0, m.rows, [&](int r) {
    Eigen::VectorXf x(shape.dims());
    for (int c = 0; c < m.cols; ++c) {
      float* v = x.data();
      const auto at = [&](int i, int j) { return t.rgb.at(t.wrapX(c * step + i), t.wrapY(r * step + j)); };
      for (int j = shape.lo(); j <= shape.hi(); ++j)
        for (int i = shape.lo(); i <= shape.hi(); ++i)
          writePixelFeatures(shape, at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1), v);
      const Eigen::VectorXf reduced = en.pca.project(x);
      const std::int32_t best = tree.nearest(reduced.data());
      const std::size_t id = std::size_t(r) * std::size_t(m.cols) + std::size_t(c);
      m.match[id] = best;
      m.distance[id] = (x - en.full.col(best)).squaredNorm();
    }
  });
  return m;
}

/// Kwatra et al.'s optimisation step: every pixel becomes the IRLS-weighted average of the exemplar
/// pixels the covering neighbourhoods' matches propose; its source is the proposal of largest weight.
void solve(Texture& t, const RgbImage& exemplar, const ExemplarNeighborhoods& en, const Matches& m,
           double irlsExponent) {
  const NeighborhoodShape& shape = en.shape;
  const double exponent = (irlsExponent - 2.0) / 2.0, eps = 1e-4 * shape.dims();
  std::vector<float> weight(m.distance.size());
  for (std::size_t i = 0; i < weight.size(); ++i) weight[i] = float(std::pow(m.distance[i] + eps, exponent));
  tbb::parallel_for(0, t.rgb.height, [&](int y) {
    for (int x = 0; x < t.rgb.width; ++x) {
      double sum[3] = {0, 0, 0}, total = 0, strongest = -1;
      std::int32_t dominant = -1;
      for (int j = shape.lo(); j <= shape.hi(); ++j) {
        const int cy = t.wrapY(y - j);
        if (cy % m.step != 0) continue;
        for (int i = shape.lo(); i <= shape.hi(); ++i) {
          const int cx = t.wrapX(x - i);
          if (cx % m.step != 0) continue;
          const std::size_t id = std::size_t(cy / m.step) * std::size_t(m.cols) + std::size_t(cx / m.step);
          const std::int32_t match = m.match[id];
          const std::int32_t pixel = (en.centreY(match) + j) * exemplar.width + en.centreX(match) + i;
          const float* e = exemplar.data.data() + 3 * std::size_t(pixel);
          for (int c = 0; c < 3; ++c) sum[c] += weight[id] * e[c];
          total += weight[id];
          if (weight[id] > strongest) strongest = weight[id], dominant = pixel;
        }
      }
      float* out = t.rgb.at(x, y);
      for (int c = 0; c < 3; ++c) out[c] = float(sum[c] / total);
      t.source[std::size_t(y) * t.rgb.width + x] = dominant;
    }
  });
}

/// Heeger and Bergen's histogram matching: every channel's values take the exemplar's value at the
/// same rank (ties by pixel order), so the texture's per-channel histograms equal the exemplar's.
/// Averaging erodes a minority colour (two-colour discs: 0.22-0.27 of the pixels for the exemplar's
/// 0.30); matching after every step keeps it, and the textures sharper.
void matchHistograms(RgbImage& t, const RgbImage& exemplar) {
  const std::size_t n = std::size_t(t.pixelCount()), m = std::size_t(exemplar.pixelCount());
  std::vector<std::uint32_t> order(n);
  std::vector<float> target(m);
  for (int c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < m; ++i) target[i] = exemplar.data[3 * i + std::size_t(c)];
    std::sort(target.begin(), target.end());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
      return t.data[3 * a + std::size_t(c)] < t.data[3 * b + std::size_t(c)];
    });
    for (std::size_t r = 0; r < n; ++r)
      t.data[3 * order[r] + std::size_t(c)] = target[std::min(m - 1, (2 * r + 1) * m / (2 * n))];
  }
}

double meanRmsDistance(const Matches& m, int dims) {
  double sum = 0;
  for (float d : m.distance) sum += std::sqrt(double(d) / dims);
  return m.distance.empty() ? 0.0 : sum / double(m.distance.size());
}

TextureLevelStatistics optimizeLevel(int l, int levels, const ExemplarPyramid& pyramid, int neighborhood,
                                     const TextureSynthesisOptions& o, Texture& texture) {
  const auto start = Clock::now();
  const RgbImage& ex = pyramid.levels[std::size_t(l)];
  const int shift = levels - 1 - l;
  const ExemplarNeighborhoods en = buildExemplarNeighborhoods(
      ex, NeighborhoodShape{neighborhood, o.distance == NeighborhoodDistance::Wavelet}, o.pcaDims);
  const KdTree tree(en.reduced.data(), en.count(), en.reducedDims());
  TextureLevelStatistics stats{
      o.width >> shift, o.height >> shift, ex.width, ex.height, neighborhood, 0, {}, 0};
  stats.analysisSeconds = secondsSince(start);
  texture = l == 0 ? randomTexture(stats.width, stats.height, ex, deriveSeed(o.seed, 0))
                   : upsample(texture, pyramid.levels[std::size_t(l - 1)].width, ex);
  for (int it = 0; it < o.iterations; ++it) {
    checkInterruption();
    const Matches matches = search(texture, en, tree, o.sparseStep);
    stats.energies.push_back(meanRmsDistance(matches, en.shape.dims()));
    solve(texture, ex, en, matches, o.irlsExponent);
    matchHistograms(texture.rgb, ex);
    if (o.progress) {
      std::ostringstream line;
      line << textureMethodName(o.method) << " level " << l + 1 << "/" << levels << " (" << stats.width << "x"
           << stats.height << ") iteration " << it + 1 << "/" << o.iterations << " energy "
           << stats.energies.back();
      const auto pixels = [&](int level) {
        return double(o.width >> (levels - 1 - level)) * double(o.height >> (levels - 1 - level));
      };
      o.progress(line.str(), pyramidFraction(levels, l, it, o.iterations, pixels));
    }
  }
  stats.seconds = secondsSince(start);
  return stats;
}

cv::Mat toMat(const RgbImage& image) {
  cv::Mat out(image.height, image.width, CV_32FC3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.at(x, y);
      out.at<cv::Vec3f>(y, x) = {std::clamp(p[0], 0.0f, 1.0f), std::clamp(p[1], 0.0f, 1.0f),
                                 std::clamp(p[2], 0.0f, 1.0f)};
    }
  return out;
}

}  // namespace

TextureSynthesisResult synthesizeTexture(const cv::Mat& exemplarSrgb, const TextureSynthesisOptions& o) {
  const auto start = Clock::now();
  TextureSynthesisResult result;
  result.neighborhoods = validate(exemplarSrgb, o);
  const ThreadLimit threadLimit(o.threads);

  const int rebuilt = o.method == TextureMethod::Skeletal ? o.waveletLevels : 0;
  RgbImage finest = toRgbImage(exemplarSrgb);
  std::optional<HaarPyramid> haar;
  if (rebuilt > 0) {
    haar = buildHaarPyramid(finest, rebuilt);
    finest = haar->finest;
  }
  ExemplarPyramid pyramid = buildExemplarPyramid(finest, o.levels);
  const int optimised = o.levels - rebuilt;
  pyramid.levels.resize(std::size_t(optimised));
  TextureSynthesisOptions coarse = o;
  coarse.width = o.width >> rebuilt;
  coarse.height = o.height >> rebuilt;
  Texture texture;
  for (int l = 0; l < optimised; ++l)
    result.levels.push_back(
        optimizeLevel(l, optimised, pyramid, result.neighborhoods[std::size_t(l)], coarse, texture));
  if (haar) {
    const auto rebuildStart = Clock::now();
    texture.rgb = rebuildFromSources(texture.rgb, texture.source, *haar);
    result.rebuildSeconds = secondsSince(rebuildStart);
  }
  result.image = toMat(texture.rgb);
  result.seconds = secondsSince(start);
  return result;
}

}  // namespace solidtex
