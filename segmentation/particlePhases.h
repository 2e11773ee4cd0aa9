#pragma once
/// @file particlePhases.h
/// @brief The photo's particles sorted into phases (kinds of particle) by their colour and grain.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "segmentation/ExemplarStats.h"

namespace solidtex {

/// The most phases a photo's particles are sorted into.
inline constexpr int kMaxPhases = 8;

/// How the photo's particles are sorted into phases.
struct PhaseOptions {
  /// 1: one phase (or the mask's); kAutoPhases: the count the colours' BIC chooses; 2 to 8.
  int phases = 1;
  /// A label image of the photo, one phase per distinct value (at most `phases` when that is 2 or
  /// more), in place of the colours' k-means.
  std::optional<std::string> maskPath;
  /// Asks for phases at all: a count other than one, or a mask.
  bool any() const { return phases != 1 || maskPath.has_value(); }
};

/// PhaseOptions::phases for the count the colours' BIC chooses (`--phases auto`).
inline constexpr int kAutoPhases = 0;

/// The particles' phases and how they were found.
struct ParticlePhases {
  /// K x 4 CV_32F, each phase's CIE L*a*b* (D65) colour and grain contrast (grainContrast, L*
  /// units): darkest first (classifyParticles), in the mask's order of values
  /// (particlePhasesOfLabels), as given (nearestPhases, where K x 3 centres are colours alone).
  cv::Mat centres;
  std::vector<int> phaseOf;  ///< per ExemplarStats::particles index, 0..K-1
  /// With the count chosen automatically: the Bayesian information criterion of 1, 2, ... phases
  /// (the lowest of the counts whose phases all hold enough particles won); empty otherwise.
  std::vector<double> bic;
  std::string method;  ///< how the phases were found, for reports
};

/// k-means (OpenCV, k-means++ seeded from `seed`, 3 attempts) of the particles' mean colours in
/// CIE L*a*b* and their grain contrast (in L* units; a particle too small to show its grain takes
/// the median of those that do; with none that does, colours alone and K x 3 centres), each
/// particle one sample. `phases` 0 chooses the count, 1 to 8 or
/// the number of particles, by the lowest BIC of the Gaussian mixture (full or spherical
/// covariances, the better) the clustering stands for, among the counts whose every phase holds at
/// least two particles and 1 % of them. Throws OptionError for `phases` outside [0, 8], InputError for
/// fewer particles than phases.
ParticlePhases classifyParticles(const ExemplarStats& stats, int phases, std::uint64_t seed);

/// The phases a label image gives: one per distinct colour (8 bits a channel), in increasing order
/// of its packed RGB value; each particle takes the value most of its pixels show, each centre is
/// the mean colour and grain of its particles. `labelImage` is CV_32FC3 in [0, 1] (loadPhoto's form). Throws
/// InputError, naming `name`, unless it is the photo's size and has 1 to `maxPhases` values.
ParticlePhases particlePhasesOfLabels(const ExemplarStats& stats, const cv::Mat& labelImage,
                                      const std::string& name, int maxPhases = kMaxPhases);

/// The phase of the nearest centre (colour and grain, or colour alone for K x 3 centres) of every
/// particle: how another photo's (or a re-segmented photo's) particles are sorted into phases
/// already found.
ParticlePhases nearestPhases(const ExemplarStats& stats, const cv::Mat& centres);

/// The phases `options` ask for (classifyParticles, or particlePhasesOfLabels of the mask read
/// from its file); none when they ask for one phase.
std::optional<ParticlePhases> findPhases(const ExemplarStats& stats, const PhaseOptions& options,
                                         std::uint64_t seed);

/// CIE L*a*b* of linear-RGB colours, one row each (K x 3 CV_32F): phase colours as the centres'
/// first three columns hold them.
cv::Mat labOfColours(const std::vector<cv::Vec3f>& linear);

/// Writes the phases into the statistics (Particle2D::phase, ExemplarStats::phaseCentres).
void assignPhases(ExemplarStats& stats, const ParticlePhases& phases);

/// Each phase's share of the photo's area (its particles' pixels over all pixels).
std::vector<double> phaseAreaFractions(const ExemplarStats& stats);

/// The statistics of one phase's particles alone: its particles (ids kept), their area histogram
/// and box sizes, and their area fraction.
ExemplarStats phaseStats(const ExemplarStats& stats, int phase);

}  // namespace solidtex
