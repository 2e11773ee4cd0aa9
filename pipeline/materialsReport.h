#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "common/Grid.h"
#include "validation/PhaseField.h"
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

/// One phase of a photo (at the solid's scale) and of a solid; particle labels for the cluster
/// function C2 when the phase is a particle phase (else empty).
struct PhasePair {
  std::string name;
  PhaseField photo, solid;
  std::vector<std::int32_t> photoLabels, solidLabels;
};

/// The particles (label > 0) and the matrix of a photo's label image (CV_32S at the solid's scale)
/// and of a solid's particle ids.
std::vector<PhasePair> particleAndMatrixPhases(const cv::Mat& photoLabels, const Dims& dims,
                                               const std::vector<std::int32_t>& ids);

/// The phases of a photo's class image (CV_32S, 0..K-1, at the solid's scale) and of the solid's
/// voxel classes (`classes` per voxel): "phase_0" .. "phase_{K-1}".
std::vector<PhasePair> classPhases(const cv::Mat& photoClasses, const Dims& dims,
                                   const std::vector<std::uint8_t>& classes, int count);

/// The descriptors of each phase of the photo, of the solid's axis sections and of the solid in 3D,
/// with the distances between the photo's curves and the sections' and the solid's.
nlohmann::json materialsReport(const std::vector<PhasePair>& phases, const MaterialsOptions& options);

}  // namespace solidtex
