#include "placement/phaseShares.h"

#include <algorithm>
#include <numeric>

#include <tbb/parallel_for.h>

#include "common/Random.h"
#include "placement/detail/ShapeSupply.h"
#include "segmentation/particlePhases.h"

namespace solidtex {
namespace {

// Shapes whose mean volume stands for a phase's: its sizes spread the volumes over a factor of ten
// or so, and a mean of 128 is then known to a few per cent.
constexpr int kShapesPerPhase = 128;
constexpr std::uint64_t kPhaseShapeStream = 0x7068617365;  // "phase"

// The mean voxels of shapes made for the phase's particles (`members`), drawn by weight.
double meanShapeVolume(const ExemplarStats& stats, const ParticleFactory& factory,
                       const std::vector<std::size_t>& members, const std::vector<double>& weights,
                       double voxelsPerPixel, std::uint64_t seed) {
  std::vector<double> cumulative(members.size());
  double total = 0;
  for (std::size_t j = 0; j < members.size(); ++j) cumulative[j] = total += weights[members[j]];
  std::vector<double> volumes(kShapesPerPhase);
  tbb::parallel_for(0, kShapesPerPhase, [&](int s) {
    Rng rng(deriveSeed(seed, std::uint64_t(s)));
    const double draw = uniform01(rng) * total;
    const auto j =
        std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), draw) - cumulative.begin());
    const Particle2D& member = stats.particles[members[std::min(j, members.size() - 1)]];
    const ParticleSize size = factory.pickDepth(member.box.width, member.box.height, rng, member.phase);
    volumes[std::size_t(s)] =
        double(placement::detail::makeScaled(factory, size, voxelsPerPixel, rng).voxelCount());
  });
  return std::accumulate(volumes.begin(), volumes.end(), 0.0) / kShapesPerPhase;
}

}  // namespace

std::vector<double> phaseBalancedWeights(const ExemplarStats& stats, const ParticleFactory& factory,
                                         std::vector<double> weights, double voxelsPerPixel,
                                         std::uint64_t seed) {
  const int phases = stats.phaseCentres.rows;
  if (phases < 2) return weights;
  if (weights.empty()) weights.assign(stats.particles.size(), 1.0);
  const std::vector<double> areaShares = phaseAreaFractions(stats);
  const std::vector<std::size_t> counted = statisticalParticles(stats.particles);
  std::vector<double> volumes(std::size_t(phases), 0.0);
  for (int k = 0; k < phases; ++k) {
    std::vector<std::size_t> members;
    double weight = 0;
    for (std::size_t i : counted)
      if (stats.particles[i].phase == k) members.push_back(i), weight += weights[i];
    if (members.empty()) continue;
    // A phase the sizing left without weight (its sections all taken for cuts of another phase's
    // particles) is sized by its photo frequencies.
    if (!(weight > 0)) {
      for (std::size_t i : members) weights[i] = 1;
      weight = double(members.size());
    }
    volumes[std::size_t(k)] =
        weight * meanShapeVolume(stats, factory, members, weights, voxelsPerPixel,
                                 deriveSeed(seed, kPhaseShapeStream + std::uint64_t(k)));
  }
  const double areaTotal = std::accumulate(areaShares.begin(), areaShares.end(), 0.0);
  const double volumeTotal = std::accumulate(volumes.begin(), volumes.end(), 0.0);
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const auto k = std::size_t(stats.particles[i].phase);
    weights[i] *= volumes[k] > 0 ? (areaShares[k] / areaTotal) / (volumes[k] / volumeTotal) : 0.0;
  }
  return weights;
}

}  // namespace solidtex
