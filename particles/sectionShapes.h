#pragma once
/// @file
/// The shapes of random plane sections of a factory's particles beside the photo's own particles,
/// both at the solid's voxels: what the shape fits compare.

#include <cstdint>

#include "common/Random.h"
#include "particles/ParticleFactory.h"
#include "segmentation/ExemplarStats.h"
#include "segmentation/regionShape.h"

namespace solidtex {

/// Regions smaller than this (voxels) are too coarse to have a shape.
inline constexpr double kMinShapeArea = 20;

/// The photo's statistical particles as the solid would show them: masks resampled to
/// `voxelsPerPixel`, those of at least kMinShapeArea voxels.
ShapeColumns photoShapes(const ExemplarStats& stats, double voxelsPerPixel);

/// Which of a turned particle's grid axes a random section is cut across.
enum class SectionAxis {
  Uniform,   ///< each alike (the smoothing fit's cuts)
  ByExtent,  ///< with the particle's extent along it: the chance a random plane meets the particle
};

/// Random plane sections of `shapes` particles made at the sizes of random statistical photo
/// particles times `voxelsPerPixel * sizeFactor`, `planesPerShape` each, those of at least
/// kMinShapeArea voxels; aligned particles are cut across z. Deterministic for the state of `rng`.
ShapeColumns sectionShapes(const ExemplarStats& stats, const ParticleFactory& factory, double voxelsPerPixel,
                           double sizeFactor, int shapes, int planesPerShape, SectionAxis cuts, Rng& rng);

}  // namespace solidtex
