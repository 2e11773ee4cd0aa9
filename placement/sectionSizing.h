#pragma once
#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "particles/ParticleFactory.h"
#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// How the 3D particles are sized from the photo.
enum class Sizing {
  Bbox,      ///< the paper's: a photo (w,h) pair by its frequency in the photo
  Sections,  ///< pairs reweighted so that random sections of the solid match the photo's areas
};

/// "bbox" | "sections"; throws InputError otherwise.
Sizing parseSizing(const std::string& name);
const char* sizingName(Sizing sizing);

/// Column j: how many sections, per particle made for area bin j and per unit of plane spacing,
/// fall in each area bin of the photo's histogram (the stereological kernel of the particle shapes,
/// measured by cutting `shapesPerBin` factory particles, their boxes `sizeFactor` times the photo's,
/// with `planesPerShape` random planes each).
Eigen::Matrix<double, 10, 10> measureSectionKernel(const ExemplarStats& stats, const ParticleFactory& factory,
                                                   double voxelsPerPixel, double sizeFactor, std::uint64_t seed,
                                                   int shapesPerBin = 16, int planesPerShape = 32);

/// Non-negative least squares (Lawson and Hanson): argmin |A x - b| subject to x >= 0.
Eigen::VectorXd nonNegativeLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b);

/// The share of 3D particles per area bin whose random sections reproduce the photo's area
/// histogram through `kernel` (Saltykov-style unfolding by NNLS); bins the photo lacks stay 0.
std::array<double, 10> unfoldBinRatios(const Eigen::Matrix<double, 10, 10>& kernel,
                                       const std::array<double, 10>& photoRatios);

/// Particle sizes whose random sections reproduce the photo's areas.
struct SectionSizing {
  double sizeFactor = 1;               ///< 3D boxes are this many times the photo's (w,h) and depth
  std::array<double, 10> binRatios{};  ///< share of particles per area bin
  double residual = 0;                 ///< |predicted - photo| / |photo| of the section-area histogram
};

/// Unfolds the photo's area histogram at size factors 1, 1.1, ..., 2 and keeps the best fit: a
/// plane rarely cuts a particle through its largest section, so the particles must be larger than
/// their sections, by more when the photo's sizes are narrowly spread.
SectionSizing fitSectionSizing(const ExemplarStats& stats, const ParticleFactory& factory, double voxelsPerPixel,
                               std::uint64_t seed);

} // namespace solidtex
