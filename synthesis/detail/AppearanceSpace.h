#pragma once
// Internal: Su 2008 chapter 3.1-3.2 for one pyramid level of a volume exemplar.
#include <array>
#include <cstdint>
#include <vector>

#include "common/DenseVolume.h"

namespace solidtex::synthesis::detail {

/// Settings of one appearance-space level.
struct AppearanceOptions {
  int window = 5;     ///< side of the cubic neighbourhood each feature vector is made of
  int pcaDims = 8;    ///< dimensions kept
  int k = 3;          ///< similarity set size (the voxel itself first)
  int exclusion = 7;  ///< each later member lies outside this cube around the earlier ones
  int pcaSamples = 20000;
};

/// The exemplar's usable domain: the voxels whose window fits inside it at spacing 1, indexed from 0
/// and treated as a torus so that synthesis coordinates can wrap (thesis 3.1: the border is dropped).
struct ExemplarDomain {
  std::array<int, 3> size{};  ///< voxels per axis
  int border = 0;             ///< exemplar voxel = domain voxel + border

  std::size_t count() const { return std::size_t(size[0]) * std::size_t(size[1]) * std::size_t(size[2]); }
  std::size_t index(int x, int y, int z) const {
    return (std::size_t(z) * std::size_t(size[1]) + std::size_t(y)) * std::size_t(size[0]) + std::size_t(x);
  }
  /// Wraps a coordinate into [0, size[axis]).
  int wrap(int axis, int c) const {
    const int s = size[std::size_t(axis)];
    return ((c % s) + s) % s;
  }
};

/// The domain of an exemplar for a given window side; throws InputError when nothing is left.
ExemplarDomain exemplarDomain(const Dims& exemplar, int window);

/// One level of the Gaussian stack in appearance space.
struct AppearanceLevel {
  int dims = 0;             ///< feature dimensions
  double keptVariance = 0;  ///< of the window vectors, by the PCA
  /// Share of voxels whose set has members inside another's exclusion cube: too few similar voxels
  /// outside them among the nearest searched.
  double excludedFallbackShare = 0;
  std::vector<float> features;        ///< domain.count() x dims
  std::vector<std::int32_t> similar;  ///< domain.count() x k domain indices, the voxel itself first

  const float* feature(std::size_t i) const { return &features[i * std::size_t(dims)]; }
};

/// Features (window-side cubes of the exemplar blurred to the spacing, sampled every `spacing`
/// voxels, reduced by PCA) and similarity sets of every domain voxel. Parallel; the result does
/// not depend on the thread count.
AppearanceLevel buildAppearanceLevel(const DenseVolume& exemplar, const ExemplarDomain& domain, int spacing,
                                     const AppearanceOptions& options);

}  // namespace solidtex::synthesis::detail
