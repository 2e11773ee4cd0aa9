#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "common/DenseVolume.h"

namespace solidtex {

/// What measureVolumeQuality samples and compares.
struct VolumeQualityOptions {
  int patch = 5;           ///< cubic patch side (odd) of the 3D measures
  int samples = 4096;      ///< output patches sampled (coherence) and exemplar patches sampled (completeness)
  std::uint64_t seed = 1;  ///< where the samples lie and how the shuffled copy is shuffled
  int slicesPerAxis = 8;   ///< slice measures: evenly spaced axis-aligned slices of output and exemplar
  int slicePatch = 5;      ///< square patch side (odd) of the slice measures
  /// Principal components of the exemplar's patches that the nearest-patch search indexes (plus one
  /// coordinate, the norm of the rest of the patch).
  int searchDims = 24;
  /// Most target patches one nearest-patch search examines before it stops without proof that it
  /// found the nearest (its distance is then an upper bound); see VolumeQuality::exactShare.
  int searchBudget = 1024;
};

/// A volume synthesised from a volume exemplar, against that exemplar. Distances are RMS differences
/// per component (density or linear RGB, in [0,1]) between patches; lower is closer. The shuffled
/// figures measure a copy of the output whose voxels are randomly permuted (the same samples): the level
/// of an output with the right values and no structure.
struct VolumeQuality {
  /// Mean over sampled output patches of the distance to the nearest exemplar patch.
  double coherence = 0;
  /// Mean over sampled exemplar patches of the distance to the nearest output patch.
  double completeness = 0;
  double shuffledCoherence = 0;
  double shuffledCompleteness = 0;
  /// 2D coherence and completeness of square patches of the output's slices normal to x, y and z
  /// against the exemplar's slices normal to the same axis.
  std::array<double, 3> sliceCoherence{}, sliceCompleteness{};
  std::array<double, 3> shuffledSliceCoherence{}, shuffledSliceCompleteness{};
  /// Per channel, Wasserstein-1 distance between the output's and the exemplar's voxel values.
  std::vector<double> valueWasserstein;
  /// Share of the nearest-patch searches (3D and slices) proven to have found the nearest patch, for
  /// the output and for its shuffled copy; the others report an upper bound.
  double exactShare = 1, shuffledExactShare = 1;
  double seconds = 0;  ///< wall-clock time of the measure

  /// Coherence against the no-structure level: about 1 for an output without the exemplar's
  /// structure, 0 for a copy; <= 0.5 is the target for good synthesis.
  double coherenceRatio() const { return coherence / shuffledCoherence; }
  double completenessRatio() const { return completeness / shuffledCompleteness; }
  double meanSliceCoherence() const { return mean3(sliceCoherence); }
  double meanSliceCompleteness() const { return mean3(sliceCompleteness); }
  double sliceCoherenceRatio() const { return meanSliceCoherence() / mean3(shuffledSliceCoherence); }

private:
  static double mean3(const std::array<double, 3>& a) { return (a[0] + a[1] + a[2]) / 3; }
};

/// Measures `output` against `exemplar` (the same channel count; sizes may differ). The nearest-patch
/// searches run over every patch of the other volume that lies wholly inside it. Deterministic for any
/// thread count. Throws InputError when the volumes are inconsistent or a patch does not fit.
VolumeQuality measureVolumeQuality(const DenseVolume& output, const DenseVolume& exemplar,
                                   const VolumeQualityOptions& options = {});

}  // namespace solidtex
