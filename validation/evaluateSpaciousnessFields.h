#pragma once
/// @file evaluateSpaciousnessFields.h
/// @brief The four spaciousness fields against the exact Euclidean distance on one scene.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/Grid.h"
#include "placement/SpaciousnessField.h"

namespace solidtex {

/// Signed errors, field minus exact, in voxels.
struct ErrorSummary {
  std::size_t count = 0;
  double meanError = 0, maxError = 0;
  double meanAbsError = 0, p95AbsError = 0, maxAbsError = 0;
};

/// A field's best fit for `radius` against the exact one: the smallest exact spaciousness of at least
/// `radius`. It agrees when its spot holds the radius (less the field's slack) and is at most one
/// voxel more spacious than the exact best fit.
struct BestFitCheck {
  double radius = 0;
  std::optional<double> exactBestFit;  ///< none: no voxel is that spacious
  std::optional<double> exactAtSpot;   ///< none: the field found no spot
  bool agrees = false;
};

struct FieldEvaluation {
  PlacerKind kind = PlacerKind::Edt;
  double seconds = 0;       ///< to build the field from the scene's particles
  ErrorSummary freeVoxels;  ///< at every voxel no particle covers
  /// At the Delaunay field's circumcentre candidates; Delaunay's own are the values its best fit
  /// ranks by, the others' their at().
  ErrorSummary circumcentres;
  /// The errors that show what the field offers: at the free voxels, for Delaunay (whose at() is a
  /// nearest-vertex bound) at its circumcentres.
  std::vector<double> errors;
  std::vector<BestFitCheck>
      bestFits;  ///< at a quarter, half, three quarters and all of the largest empty ball
};

struct SpaciousnessEvaluation {
  std::vector<FieldEvaluation> fields;  ///< discrete, brute, edt, delaunay
  std::size_t circumcentres = 0;
  double largestExactEmptyBall = 0;
  double largestCircumsphereCandidate = 0;
  double exactSeconds = 0;
};

/// Count, means and extremes of signed errors; the 95th percentile of their absolute values.
ErrorSummary summarizeErrors(std::vector<double> errors);

/// Builds every field from the particles of `ids` (0 free, 1..P in the order they were placed; one
/// per voxel of a non-empty `dims`; periodic: a 3D torus) and measures it against exactSpaciousness.
/// `progress` is told each step's name; it may be empty.
SpaciousnessEvaluation evaluateSpaciousnessFields(
    const Dims& dims, const std::vector<std::int32_t>& ids, float radiusCap, std::uint64_t seed,
    const std::function<void(const std::string&)>& progress = {}, bool periodic = false);

}  // namespace solidtex
