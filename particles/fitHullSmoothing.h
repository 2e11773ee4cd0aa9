#pragma once
/// @file
/// Choosing how far to round the particles so that their sections have the photo's shapes.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "particles/ParticleFactory.h"
#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// The smoothing chosen and how close its sections' shapes come to the photo's particles'.
struct SmoothingFit {
  double radius = 0;       ///< HullSmoothing::radius
  double solidityKs = 1;   ///< KS of section solidity against the photo's particles, at that radius
  double roundnessKs = 1;  ///< the same for roundness
};

/// The candidate radii fitHullSmoothing tries, sharp (the paper's hulls) to well rounded.
std::vector<double> smoothingCandidates();

/// Of the candidate radii, the one whose particles (made `sizeFactor` times the photo's sizes) have
/// random plane sections closest in shape (KS of solidity plus KS of roundness, sections of at
/// least 20 samples) to the photo's statistical particles, both at `voxelsPerPixel`, the resolution
/// the solid can show. Gravel keeps its edges; pebbles, beans and coins come out round.
/// Deterministic for the seed.
SmoothingFit fitHullSmoothing(const ExemplarStats& stats, const ParticleFactory& factory,
                              double voxelsPerPixel, double sizeFactor, std::uint64_t seed);

/// "auto" (none: fit it) or a radius in [0, 0.5]; throws InputError otherwise.
std::optional<double> parseSmoothing(const std::string& text);

}  // namespace solidtex
