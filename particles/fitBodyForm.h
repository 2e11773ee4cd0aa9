#pragma once
/// @file
/// Choosing the particles' body form (disc- to rod-like) so that their sections are as elongated
/// as the photo's particles.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "particles/ParticleFactory.h"
#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// The body form chosen and how close its sections' elongation comes to the photo's particles'.
struct BodyFormFit {
  double form = 0;      ///< ParticleOptions::bodyForm
  double aspectKs = 1;  ///< KS of section aspect (minor / major axis) against the photo's particles
};

/// The candidate forms fitBodyForm tries, rods to discs; 0 is the paper's boxes.
std::vector<double> bodyFormCandidates();

/// Of the candidate forms, the one whose particles have random plane sections closest in aspect
/// (KS; sections of at least 20 samples at `voxelsPerPixel`) to the photo's statistical
/// particles. Flattened grains come out as discs, not as the triaxial bodies their sections' boxes
/// make. Deterministic for the seed. Aligned factories keep their boxes (form 0, not fitted).
BodyFormFit fitBodyForm(const ExemplarStats& stats, const ParticleFactory& factory, double voxelsPerPixel,
                        std::uint64_t seed);

/// "auto" (none: fit it) or a form in [-1, 1]; throws InputError otherwise.
std::optional<double> parseBodyForm(const std::string& text);

}  // namespace solidtex
