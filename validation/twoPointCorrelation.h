#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "validation/PhaseField.h"

namespace solidtex {

/// How twoPointCorrelation estimates S2.
struct TwoPointOptions {
  int maxDistance = 0;    ///< largest separation in voxels; <= 0: a quarter of the shortest side used
  bool periodic = false;  ///< the field is a torus; otherwise zero-padded, normalised by the overlap count
};

/// A correlation function of separation: along each axis (r = 0..maxDistance voxels; empty for an
/// axis the field is flat in) and radially (the mean over every separation vector whose length
/// rounds to r).
struct CorrelationCurves {
  std::array<std::vector<double>, 3> axes;
  std::vector<double> radial;
  double phaseFraction = 0;
  /// Where the radial curve's excess over its limit at infinity (phi^2 for S2, 0 for C2) first drops
  /// to 1/e of its value at r = 0, interpolated linearly; maxDistance + 1 when it never does.
  double correlationLength = 0;
};

/// The two-point correlation S2(r) of a phase: the probability that both ends of a segment r lie in
/// it (Torquato's normalisation: S2(0) = phi, S2 -> phi^2), by FFT (FFTW).
CorrelationCurves twoPointCorrelation(const PhaseField& phase, const TwoPointOptions& options = {});

/// The two-point cluster function C2(r) of labelled particles (label > 0): the probability that both
/// ends of r lie in the same particle (C2(0) = phi, C2 -> 0). Along the axes only, by scanning lines;
/// never periodic.
CorrelationCurves twoPointClusterFunction(const Dims& dims, const std::vector<std::int32_t>& labels,
                                          int maxDistance = 0);

/// The separation twoPointCorrelation uses for `maxDistance` on a field of `dims`.
int correlationMaxDistance(const Dims& dims, int maxDistance);

/// The mean of the curves along the axes a field extends in (the others are empty).
std::vector<double> meanOverAxes(const std::array<std::vector<double>, 3>& axes);

/// Root mean square difference of two curves over their common length.
double curveDistance(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace solidtex
