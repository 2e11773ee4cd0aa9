#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "common/Grid.h"
#include "validation/tortuosity.h"

namespace solidtex {

/// The materials descriptors `compare --measures` computes.
struct MeasureSelection {
  bool twoPoint = true;     ///< s2: two-point correlation (and the particles' cluster function C2)
  bool linealPath = true;   ///< lineal
  bool chords = true;       ///< chord
  bool sizes = true;        ///< psd: local thickness
  bool minkowski = true;    ///< minkowski
  bool tortuosity = false;  ///< tortuosity: of the solid, along each axis

  bool any() const { return twoPoint || linealPath || chords || sizes || minkowski || tortuosity; }
};

/// Parses a comma-separated list of s2, lineal, chord, psd, minkowski, tortuosity, or "all" or
/// "none"; throws OptionError otherwise.
MeasureSelection parseMeasureSelection(const std::string& list);

/// How the materials report samples its fields.
struct MaterialsOptions {
  MeasureSelection measures;
  int maxDistance = 0;    ///< of the correlation curves, voxels; <= 0: a quarter of the photo's shorter side
  int planesPerAxis = 3;  ///< axis sections of the solid, evenly spaced, per axis
  bool periodic = false;  ///< the solid is a torus (its two-point correlation wraps around)
  TortuosityOptions tortuosity;
};

/// The descriptors of the particle phase and the matrix of a photo's label image (CV_32S at the
/// solid's scale, 0 = matrix), of the solid's axis sections and of the solid (an id volume) in 3D,
/// with the distances between the photo's curves and the sections' and the solid's.
nlohmann::json materialsReport(const cv::Mat& photoLabels, const Dims& dims,
                               const std::vector<std::int32_t>& ids, const MaterialsOptions& options);

}  // namespace solidtex
