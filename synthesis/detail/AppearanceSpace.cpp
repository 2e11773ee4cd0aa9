#include "synthesis/detail/AppearanceSpace.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <tbb/parallel_for.h>

#include "common/Error.h"
#include "common/Random.h"
#include "common/gaussianFilter.h"
#include "synthesis/detail/InvertedFileIndex.h"
#include "synthesis/detail/KdTree.h"
#include "synthesis/detail/Pca.h"

namespace solidtex::synthesis::detail {
namespace {

// The Gaussian stack's level for a spacing: blurred over about half the spacing, so that samples
// `spacing` apart see the structure at that scale rather than aliased detail.
DenseVolume stackLevel(const DenseVolume& exemplar, int spacing) {
  if (spacing <= 1) return exemplar;
  const std::vector<float> kernel = gaussianKernel(0.5 * spacing);
  DenseVolume blurred = exemplar,
              scratch{exemplar.dims, exemplar.channels, std::vector<float>(exemplar.values.size())};
  for (int axis = 0; axis < 3; ++axis) {
    correlateAlong(blurred.values.data(), scratch.values.data(), blurred.dims, blurred.channels, axis,
                   kernel);
    std::swap(blurred.values, scratch.values);
  }
  return blurred;
}

// The window vector of domain voxel (x,y,z): window^3 samples `spacing` apart, C values each.
// Samples outside the exemplar wrap into the domain.
void windowVector(const DenseVolume& level, const ExemplarDomain& domain, int window, int spacing, int x,
                  int y, int z, float* out) {
  const int half = window / 2;
  const std::array<int, 3> n{level.dims.x, level.dims.y, level.dims.z};
  auto sample = [&](int axis, int domainCoordinate, int offset) {
    const int e = domainCoordinate + domain.border + spacing * offset;
    return e >= 0 && e < n[std::size_t(axis)] ? e : domain.border + domain.wrap(axis, e - domain.border);
  };
  for (int c = -half; c <= half; ++c) {
    const int ez = sample(2, z, c);
    for (int b = -half; b <= half; ++b) {
      const int ey = sample(1, y, b);
      for (int a = -half; a <= half; ++a) {
        const float* v = level.at(sample(0, x, a), ey, ez);
        out = std::copy_n(v, level.channels, out);
      }
    }
  }
}

Eigen::MatrixXf windowVectors(const DenseVolume& level, const ExemplarDomain& domain, int window, int spacing,
                              const std::vector<std::size_t>& voxels) {
  const int D = window * window * window * level.channels;
  Eigen::MatrixXf out(D, Eigen::Index(voxels.size()));
  for (std::size_t s = 0; s < voxels.size(); ++s) {
    const std::size_t v = voxels[s];
    const int x = int(v % std::size_t(domain.size[0]));
    const int y = int(v / std::size_t(domain.size[0]) % std::size_t(domain.size[1]));
    const int z = int(v / (std::size_t(domain.size[0]) * std::size_t(domain.size[1])));
    windowVector(level, domain, window, spacing, x, y, z, out.col(Eigen::Index(s)).data());
  }
  return out;
}

Pca fitWindowPca(const DenseVolume& level, const ExemplarDomain& domain, int spacing,
                 const AppearanceOptions& options) {
  std::vector<std::size_t> voxels;
  if (domain.count() <= std::size_t(options.pcaSamples)) {
    voxels.resize(domain.count());
    for (std::size_t v = 0; v < voxels.size(); ++v) voxels[v] = v;
  } else {
    Rng rng(deriveSeed(0x52008, std::uint64_t(spacing)));
    for (int s = 0; s < options.pcaSamples; ++s)
      voxels.push_back(std::size_t(uniformIndex(rng, domain.count())));
  }
  return fitPca(windowVectors(level, domain, options.window, spacing, voxels), options.pcaDims);
}

std::vector<float> projectAll(const DenseVolume& level, const ExemplarDomain& domain, int spacing,
                              const AppearanceOptions& options, const Pca& pca) {
  constexpr std::size_t kChunk = 2048;
  const std::size_t count = domain.count();
  std::vector<float> features(count * std::size_t(pca.dims()));
  tbb::parallel_for(std::size_t(0), (count + kChunk - 1) / kChunk, [&](std::size_t chunk) {
    std::vector<std::size_t> voxels;
    for (std::size_t v = chunk * kChunk; v < std::min(count, (chunk + 1) * kChunk); ++v) voxels.push_back(v);
    const Eigen::MatrixXf reduced =
        pca.projectAll(windowVectors(level, domain, options.window, spacing, voxels));
    std::copy_n(reduced.data(), reduced.size(), &features[chunk * kChunk * std::size_t(pca.dims())]);
  });
  return features;
}

// Chebyshev distance on the domain's torus.
int torusDistance(const ExemplarDomain& domain, std::size_t a, std::size_t b) {
  int worst = 0;
  std::size_t stride = 1;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const auto s = std::size_t(domain.size[axis]);
    const int d = std::abs(int(a / stride % s) - int(b / stride % s));
    worst = std::max(worst, std::min(d, int(s) - d));
    stride *= s;
  }
  return worst;
}

// The `searched` nearest features of every domain voxel (itself included), row by row: an exact
// kd-tree for small domains, FAISS's inverted file (seconds instead of minutes, may miss a few of
// the nearest) from SynthesisOptions::approximateFrom's 16384 voxels on, as for photo exemplars.
std::vector<std::int32_t> nearestOfAll(const std::vector<float>& features, int dims, int count,
                                       int searched) {
  std::vector<std::int32_t> ids(std::size_t(count) * std::size_t(searched));
  if (count >= 16384) {
    std::vector<float> distances(ids.size());
    InvertedFileIndex(features.data(), count, dims).knnOfAllPoints(searched, ids.data(), distances.data());
    return ids;
  }
  const KdTree tree(features.data(), count, dims);
  tbb::parallel_for(0, count, [&](int v) {
    std::vector<float> distances(static_cast<std::size_t>(searched));
    tree.knn(&features[std::size_t(v) * std::size_t(dims)], searched,
             &ids[std::size_t(v) * std::size_t(searched)], distances.data());
  });
  return ids;
}

// Thesis 3.2: the voxel itself, then its nearest in appearance space that keep out of the
// exclusion cubes of those already chosen; if too few keep out, the nearest remaining ones.
std::vector<std::int32_t> similaritySets(const std::vector<float>& features, int dims,
                                         const ExemplarDomain& domain, const AppearanceOptions& options,
                                         double& fallbackShare) {
  const int count = int(domain.count());
  const int k = std::min(options.k, count);
  const int searched = std::min(count, 8 * k + 24);
  const int reach = options.exclusion / 2;
  const std::vector<std::int32_t> nearest = nearestOfAll(features, dims, count, searched);
  std::vector<std::int32_t> similar(std::size_t(count) * std::size_t(options.k));
  std::vector<std::uint8_t> fellBack(std::size_t(count), 0);
  tbb::parallel_for(0, count, [&](int v) {
    const std::int32_t* ids = &nearest[std::size_t(v) * std::size_t(searched)];
    std::int32_t* set = &similar[std::size_t(v) * std::size_t(options.k)];
    int size = 0;
    set[size++] = v;
    for (int i = 0; i < searched && size < k; ++i) {
      if (ids[i] < 0) continue;
      const bool clear = std::none_of(set, set + size, [&](std::int32_t chosen) {
        return torusDistance(domain, std::size_t(chosen), std::size_t(ids[i])) <= reach;
      });
      if (clear) set[size++] = ids[i];
    }
    fellBack[std::size_t(v)] = size < k;
    for (int i = 0; i < searched && size < k; ++i)
      if (ids[i] >= 0 && std::find(set, set + size, ids[i]) == set + size) set[size++] = ids[i];
    while (size < options.k) set[size++] = v;
  });
  fallbackShare = double(std::count(fellBack.begin(), fellBack.end(), 1)) / double(std::max(count, 1));
  return similar;
}

}  // namespace

ExemplarDomain exemplarDomain(const Dims& exemplar, int window) {
  ExemplarDomain domain;
  domain.border = window / 2;
  const std::array<int, 3> n{exemplar.x, exemplar.y, exemplar.z};
  for (std::size_t a = 0; a < 3; ++a) {
    domain.size[a] = n[a] - 2 * domain.border;
    if (n[a] > 32767)  // synthesis stores coordinates as 16-bit integers
      throw InputError("the exemplar volume is larger than 32767 voxels along an axis");
    if (domain.size[a] < window)
      throw InputError("the exemplar volume (" + std::to_string(exemplar.x) + "x" +
                       std::to_string(exemplar.y) + "x" + std::to_string(exemplar.z) + ") is too small for " +
                       std::to_string(window) + "^3 appearance windows: each side needs at least " +
                       std::to_string(window + 2 * domain.border) + " voxels");
  }
  return domain;
}

AppearanceLevel buildAppearanceLevel(const DenseVolume& exemplar, const ExemplarDomain& domain, int spacing,
                                     const AppearanceOptions& options) {
  const DenseVolume level = stackLevel(exemplar, spacing);
  const Pca pca = fitWindowPca(level, domain, spacing, options);
  AppearanceLevel out;
  out.dims = pca.dims();
  out.keptVariance = pca.keptVariance();
  out.features = projectAll(level, domain, spacing, options, pca);
  out.similar = similaritySets(out.features, out.dims, domain, options, out.excludedFallbackShare);
  return out;
}

}  // namespace solidtex::synthesis::detail
