#pragma once
/// @file phaseShares.h
/// @brief Each phase's share of the particles' volume, set by the weights of its photo particles.
#include <cstdint>
#include <vector>

#include "particles/ParticleFactory.h"
#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// Scales each phase's particle weights (per ExemplarStats::particles index; empty: the photo's
/// frequencies, every particle 1) so that its expected share of the particles' volume is its share
/// of the photo's particle area (Delesse, phase by phase: A_A = V_V). A phase's mean particle
/// volume is measured on shapes the factory makes for its particles, drawn by weight, at
/// `voxelsPerPixel`. A phase that every weight leaves out takes its photo frequencies instead.
/// One phase: the weights unchanged. Deterministic for the seed.
std::vector<double> phaseBalancedWeights(const ExemplarStats& stats, const ParticleFactory& factory,
                                         std::vector<double> weights, double voxelsPerPixel,
                                         std::uint64_t seed);

}  // namespace solidtex
