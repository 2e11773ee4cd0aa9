#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "common/SolidVolume.h"

namespace solidtex {

/// The particles' shape family. All share the axis law (elongation, flattening, random rotation)
/// and the size law (volume of the equal-volume sphere); only the inside test differs.
enum class TruthShape {
  Ellipsoid,
  Superellipsoid,  ///< |x/a|^p + |y/b|^p + |z/c|^p <= 1: boxy with rounded edges for p > 2
  Polytope,        ///< convex hull of 12-16 points spread over the ellipsoid, each moved at random
};

/// "ellipsoid" | "superellipsoid" | "polytope"; throws InputError otherwise.
TruthShape parseTruthShape(const std::string& name);
const char* truthShapeName(TruthShape shape);

/// One population of particles: its size law and its colour in the photo.
struct ParticleClass {
  double meanRadius = 7;      ///< voxels; median of the equal-volume sphere radius
  double radiusSpread = 0.2;  ///< standard deviation of the radius' logarithm
  double share = 0.75;        ///< share of the particles, by number
  cv::Vec3f srgb{0.92f, 0.55f, 0.16f};
  /// Speckle in the photo: each pixel's sRGB value times 1 + grain x a standard normal draw (a
  /// relative standard deviation; 0 = plain), so that a class can differ by its grain alone.
  double grain = 0;
};

/// A solid with a known 3D truth, for checking a reconstruction against more than its photo.
struct ParticleTruthOptions {
  Dims dims{640, 640, 72};  ///< periodic on every axis, so no wall biases where particles sit
  double volumeFraction = 0.2;
  std::vector<ParticleClass> classes{
      {7, 0.2, 0.75, {0.92f, 0.55f, 0.16f}},   // small and orange
      {13, 0.2, 0.25, {0.25f, 0.48f, 0.88f}},  // large and blue: colour tells size
  };
  TruthShape shape = TruthShape::Ellipsoid;
  double elongation =
      1.25;  ///< stretch of the semi-axes: their logs uniform in [-ln e, ln e], centred so the product is 1
  double flatten = 1;   ///< the smallest semi-axis over the other two shrinks by this factor, volume kept
  double exponent = 4;  ///< superellipsoid exponent p (2 is the ellipsoid)
  /// Empty: every particle turned at random (an isotropic material). Otherwise its x, y, z semi-axes
  /// in these proportions (volume kept), times the random stretches, and no rotation: aligned
  /// particles, whose sections differ by plane.
  std::vector<double> anisotropy;
  cv::Vec3f backgroundSrgb{0.16f, 0.16f, 0.17f};
  double blur = 0;      ///< standard deviation of the photo's Gaussian blur, pixels, applied before the noise
  double noise = 0.02;  ///< standard deviation of the photo's pixel noise (sRGB)
  std::uint64_t seed = 1;
};

/// The truth and its photo.
struct ParticleTruth {
  SolidVolume volume;        ///< particle_id and linear colour; voxels_per_pixel 1 (the photo is a section)
  std::vector<int> classOf;  ///< class index per particle id - 1
  std::vector<double> volumes;  ///< voxels per particle id - 1 (photo pixels cubed)
  double volumeFraction = 0;
  cv::Mat photo;    ///< CV_32FC3 sRGB, the section z = dims.z / 2 (x across, y down)
  cv::Mat photoXz;  ///< the section y = dims.y / 2: x across, z down
  cv::Mat photoYz;  ///< the section x = dims.x / 2: y across, z down
};

/// Random non-overlapping particles (random sequential addition, largest first, each drawn size
/// placed at the first of many random spots where it neither overlaps nor touches another; sizes
/// that find none are left out) and one axis section rendered as the photo: each class in its
/// own colour on a plain background, with a little shading, blur and noise as a camera would add;
/// the other two middle sections rendered alike, after it, so that the photo does not depend on them.
/// Particles never touch, not even diagonally, so the photo's particles are its sections.
ParticleTruth makeParticleTruth(const ParticleTruthOptions& options);

}  // namespace solidtex
