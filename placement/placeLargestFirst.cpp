// Paper 3.8: particles are made and placed one by one, largest area bin first, at best-fit spots of
// the spaciousness field, until the volume fraction reaches the target (the photo's area fraction).
#include "placement/placeLargestFirst.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "common/Error.h"
#include "placement/detail/ShapeSupply.h"
#include "placement/detail/shapeFit.h"

namespace solidtex {
namespace {

constexpr int kBins = 10;
// A bin takes another particle while it misses more than half of one. Placing until the quota is
// met overshot it by half a particle a bin on average: a sixth to a half of the volume of the
// largest bins, which hold one to three particles in a block, taken from the smallest bin, which
// comes last (docs/validation.md, "3D sizes").
constexpr double kQuotaSlack = 0.5;
constexpr std::uint64_t kPlacementStream = 0x706c616365;  // "place"
// Radii asked of the field per shape, evenly from the spaciousness the shape needs at least (its
// inner radius) to the one with which it surely fits (its outer radius): the tightest spots are
// tried first, as best fit wants, but an irregular shape that fits none of them still finds room.
constexpr int kRadiusSteps = 4;
constexpr int kFailuresToRetire = 8;
constexpr int kMinPilotShapes = 8, kMaxPilotShapes = 96;
constexpr double kShrink = 0.85;  // particles' size per shrink step once nothing fits
constexpr int kMaxShrinks = 3;
constexpr double kPilotPrecision = 0.03;              // standard error of the mean / mean
constexpr std::uint64_t kPilotStream = 0x70696c6f74;  // "pilot"
constexpr std::uint64_t kPairStream = 0x7061697273;   // "pairs"

// A (width, height) box of the photo's particles and how often 3D particles take it.
struct WeightedPair {
  int width = 0, height = 0;
  double weight = 0;
  int particlePhase = 0;  ///< the kind of particle whose photo particles have this box
};

using BinPairs = std::array<std::vector<WeightedPair>, kBins>;
using placement::detail::ShapeKey;

// The (width, height) pairs of each area bin, from the particles the histogram counts (not cut by
// the photo's border; all when every one is), weighted by their particles' weights, or counted.
BinPairs pairsPerBin(const ExemplarStats& stats, const std::vector<double>& particleWeights) {
  std::array<std::map<std::array<int, 3>, double>, kBins> weights;
  for (std::size_t i : statisticalParticles(stats.particles)) {
    const Particle2D& p = stats.particles[i];
    const double weight = particleWeights.empty() ? 1.0 : particleWeights[i];
    if (p.box.width > 0 && p.box.height > 0 && weight > 0)
      weights[std::size_t(stats.histogram.binOf(p.area))][{p.box.width, p.box.height, p.phase}] += weight;
  }
  BinPairs pairs;
  for (int b = 0; b < kBins; ++b)
    for (const auto& [size, weight] : weights[std::size_t(b)])
      pairs[std::size_t(b)].push_back({size[0], size[1], weight, size[2]});
  return pairs;
}

double totalWeight(const std::vector<WeightedPair>& pairs) {
  double total = 0;
  for (const WeightedPair& p : pairs) total += p.weight;
  return total;
}

// One of `candidates` (indices into pairs), drawn with probability proportional to its pair's weight;
// returns its position in `candidates`.
std::size_t drawByWeight(const std::vector<WeightedPair>& pairs, const std::vector<std::size_t>& candidates,
                         Rng& rng) {
  double total = 0;
  for (const std::size_t c : candidates) total += pairs[c].weight;
  double draw = uniform01(rng) * total;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (draw < pairs[candidates[i]].weight) return i;
    draw -= pairs[candidates[i]].weight;
  }
  return candidates.size() - 1;
}

void checkOptions(const ExemplarStats& stats, const PlacementOptions& options,
                  const SpaciousnessField& field) {
  const auto& w = options.particleWeights;
  if (!w.empty() &&
      (w.size() != stats.particles.size() ||
       std::any_of(w.begin(), w.end(), [](double v) { return !(v >= 0) || !std::isfinite(v); }) ||
       !(std::accumulate(w.begin(), w.end(), 0.0) > 0)))
    throw InputError(
        "placement: particle weights must be one non-negative number per photo particle, not all 0");
  if (!(options.voxelsPerPixel > 0) || !std::isfinite(options.voxelsPerPixel))
    throw InputError("placement: voxels per pixel must be positive, got " +
                     std::to_string(options.voxelsPerPixel));
  if (!(options.sizeFactor > 0) || !std::isfinite(options.sizeFactor))
    throw InputError("placement: the size factor must be positive, got " +
                     std::to_string(options.sizeFactor));
  if (options.maxParticles < 0)
    throw InputError("placement: the particle limit must not be negative, got " +
                     std::to_string(options.maxParticles));
  if (options.candidatesPerTry < 1)
    throw InputError("placement: candidates per try must be at least 1, got " +
                     std::to_string(options.candidatesPerTry));
  if (std::any_of(options.quotaDither.begin(), options.quotaDither.end(),
                  [](double d) { return !(d >= 0 && d < 1); }))
    throw std::invalid_argument("placement: quota dithers must be in [0, 1)");
  if (!(options.firstPassShare > 0 && options.firstPassShare <= 1))
    throw std::invalid_argument("placement: the first pass's share must be in (0, 1]");
  if (options.firstPassDownTo && (*options.firstPassDownTo < 0 || *options.firstPassDownTo >= kBins))
    throw std::invalid_argument("placement: the first pass must go down to a bin in [0, 9]");
  if (options.progressEvery < 1)
    throw InputError("placement: progress must come every particle or less often, got every " +
                     std::to_string(options.progressEvery));
  const auto inside = [&](const std::optional<Box>& box) {
    return !box || (!box->empty() && options.dims.contains(box->lo.x, box->lo.y, box->lo.z) &&
                    options.dims.contains(box->hi.x - 1, box->hi.y - 1, box->hi.z - 1));
  };
  if (!inside(options.counted))
    throw std::invalid_argument("placement: the counted box is not inside the volume");
  if (!inside(options.spots))
    throw std::invalid_argument("placement: the spots' box is not inside the volume");
  if (options.ownVoxels && *options.ownVoxels == 0)
    throw std::invalid_argument("placement: a brick's own voxels must not be 0");
  for (const PlacementObstacle& o : options.obstacles)
    if (o.bin < 0 || o.bin >= kBins || o.voxelCount < o.voxels.size() ||
        (!options.periodic && std::any_of(o.voxels.begin(), o.voxels.end(), [&](const Voxel& v) {
          return !options.dims.contains(v.x, v.y, v.z);
        })))
      throw std::invalid_argument("placement: an obstacle lies outside the volume or has no valid bin");
  if (!(options.dims == field.dims()))
    throw std::invalid_argument("placement: the options' dims differ from the spaciousness field's");
  if (options.periodic != field.periodic())
    throw std::invalid_argument("placement: the options and the spaciousness field differ in periodicity");
  if (options.periodic && options.counted)
    throw std::invalid_argument("placement: a periodic volume has no margin to leave out of the count");
  const BinPairs photoPairs = pairsPerBin(stats, {});
  if (std::all_of(photoPairs.begin(), photoPairs.end(), [](const auto& pairs) { return pairs.empty(); }))
    throw InputError("placement: the photo has no particle to take sizes from");
}

// What a phase places: particles of the sizing's shares or of the photo's, at one scale. Its shapes
// and size estimates come from streams of its own (its index); the order of pairs and spots is
// drawn from streams that run on through the phases.
struct PhasePlan {
  int index = 0;
  double scale = 1;         ///< voxels per photo pixel of its particles
  bool photoShares = true;  ///< the photo's frequencies of (width, height) pairs, else the particle weights'
  int shrinks = 0;          ///< times the photo's sizes were shrunk by kShrink
};

// The phases in their order; each one starts when no bin of the one before fits any more.
std::vector<PhasePlan> phasePlans(const PlacementOptions& options) {
  const bool weighted = !options.particleWeights.empty();
  std::vector<PhasePlan> plans{
      {0, options.voxelsPerPixel * (weighted ? options.sizeFactor : 1), !weighted, 0}};
  // Shares other than the photo's can leave gaps only the photo's other sizes fit (a mix without
  // small particles jams early): the photo's shares fill the rest.
  if (weighted) plans.push_back({1, options.voxelsPerPixel, true, 0});
  // A crowded photo (touching coins, dense gravel) can ask for more than random placement packs:
  // the photo's shares are tried again smaller, kShrink at a time.
  for (int shrinks = 1; shrinks <= kMaxShrinks; ++shrinks)
    plans.push_back({shrinks + 1, options.voxelsPerPixel * std::pow(kShrink, shrinks), true, shrinks});
  return plans;
}

// Expected particle volumes per bin start from a few pilot shapes of the bin and follow the
// shapes placed since. The largest bins' counts are set before most of their shapes exist, and
// every voxel they take beyond plan is taken from the smallest bin, placed last: the start must
// be right.
PlacementPilot pilotOf(const PhasePlan& plan, const BinPairs& pairs, const ParticleFactory& factory,
                       std::uint64_t seed) {
  PlacementPilot pilot;
  tbb::parallel_for(0, kBins, [&](int b) {
    const auto& binPairs = pairs[std::size_t(b)];
    if (binPairs.empty()) return;
    std::vector<std::size_t> all(binPairs.size());
    std::iota(all.begin(), all.end(), 0);
    Rng rng(deriveSeed(seed, kPilotStream + std::uint64_t(b) + std::uint64_t(plan.index * kBins)));
    // Until the mean is known to kPilotPrecision: a bin's sizes may span a factor of ten in volume.
    double sum = 0, sumOfSquares = 0;
    int n = 0;
    while (n < kMaxPilotShapes) {
      ++n;
      const WeightedPair& pair = binPairs[all[drawByWeight(binPairs, all, rng)]];
      const ParticleSize size = factory.pickDepth(pair.width, pair.height, rng, pair.particlePhase);
      const auto voxels = double(placement::detail::makeScaled(factory, size, plan.scale, rng).voxelCount());
      sum += voxels;
      sumOfSquares += voxels * voxels;
      const double mean = sum / n, variance = std::max(0.0, sumOfSquares / n - mean * mean);
      if (n >= kMinPilotShapes && variance / n <= kPilotPrecision * kPilotPrecision * mean * mean) break;
    }
    pilot.shapes[std::size_t(b)] = n;
    pilot.voxels[std::size_t(b)] = sum;
  });
  return pilot;
}

// A phase's bins: their (width, height) pairs and shares, which are still open, the volumes their
// shapes take, and the shapes themselves.
struct Phase {
  Phase(const PhasePlan& plan, const ExemplarStats& stats, const ParticleFactory& factory,
        const PlacementOptions& options)
      : plan(plan),
        pairs(pairsPerBin(stats, plan.photoShares ? std::vector<double>{} : options.particleWeights)),
        passShare(plan.index == 0 ? options.firstPassShare : 1),
        shapes(factory, options.seed, plan.index, plan.scale) {
    double total = 0;
    for (int b = 0; b < kBins; ++b) total += share[std::size_t(b)] = totalWeight(pairs[std::size_t(b)]);
    for (int b = 0; b < kBins; ++b) {
      share[std::size_t(b)] = total > 0 ? share[std::size_t(b)] / total : 0;
      open[std::size_t(b)] = share[std::size_t(b)] > 0 && !pairs[std::size_t(b)].empty();
    }
    const PlacementPilot pilot = std::size_t(plan.index) < options.pilots.size()
                                     ? options.pilots[std::size_t(plan.index)]
                                     : pilotOf(plan, pairs, factory, options.seed);
    made = pilot.shapes;
    for (int b = 0; b < kBins; ++b) madeVoxels[std::size_t(b)] = pilot.voxels[std::size_t(b)];
  }

  // Expected voxels of a particle of bin b: the mean of the shapes made for it so far.
  double expectedVolume(int b) const {
    return made[std::size_t(b)] > 0 ? std::max(1.0, madeVoxels[std::size_t(b)] / made[std::size_t(b)]) : 1.0;
  }

  const PhasePlan plan;
  BinPairs pairs;
  std::array<double, kBins> share{};
  std::array<bool, kBins> open{};
  std::array<int, kBins> made{};  ///< pilot shapes and placed particles, whose voxels madeVoxels sums
  std::array<double, kBins> madeVoxels{};
  std::array<std::vector<int>, kBins> failures;  ///< per pair, tries that found no spot in a row
  bool roundUp = false;  ///< the last pass over the bins placed nothing: quotas round up
  double passShare;      ///< of each bin's quota that a pass places
  placement::detail::ShapeSupply shapes;
};

int spotsToAsk(const PlacementOptions& options) {
  if (!options.spots) return options.candidatesPerTry;
  const double larger = double(options.dims.count()) / double(options.spots->dims().count());
  return int(std::min(1e6, std::ceil(options.candidatesPerTry * larger)));
}

class Placer {
public:
  Placer(const ExemplarStats& stats, const ParticleFactory& factory, SpaciousnessField& field,
         const PlacementOptions& options)
      : stats_(stats),
        factory_(factory),
        field_(field),
        options_(options),
        rng_(deriveSeed(options.seed, kPlacementStream)),
        pairRng_(deriveSeed(options.seed, kPairStream)),
        counted_(options.counted.value_or(Box::of(options.dims))),
        idsBox_(options.idsEverywhere ? Box::of(options.dims) : counted_),
        fillVoxels_(options.ownVoxels.value_or(counted_.dims().count())),
        targetVoxels_(std::ceil(std::clamp(targetFraction(stats, options), 0.0, 1.0) * double(fillVoxels_))),
        occupied_(options.dims.count()),
        tried_(options.dims.count()) {
    result_.dims = options.dims;
    result_.periodic = options.periodic;
    result_.counted = counted_;
    result_.ids.assign(idsBox_.dims().count(), 0);
    takeObstacles();
  }

  // The field may still be taking the last particle when an exception leaves run(): wait for it,
  // and drop its own error, as one exception is on its way already.
  ~Placer() {
    try {
      fieldUpdate_.wait();
    } catch (...) {
    }
  }

  PlacementResult run() {
    if (targetVoxels_ <= 0) return finish("the fraction to fill is 0: nothing to place");
    if (const std::optional<int> smallest = options_.firstPassDownTo) {
      startPhase(phasePlans(options_).front());
      if (const std::optional<std::string> reason = pass(*smallest)) return finish(*reason);
      return finish("first pass down to bin " + std::to_string(*smallest) + " done");
    }
    for (const PhasePlan& plan : phasePlans(options_)) {
      startPhase(plan);
      if (const std::optional<std::string> reason = fillPhase()) return finish(*reason);
    }
    char reason[96];
    std::snprintf(reason, sizeof reason, "no bin fits any more (fraction %.3f of %.3f)", fraction(),
                  targetFraction(stats_, options_));
    return finish(reason);
  }

private:
  // The obstacles go into the field as one insertion: one update for all of them.
  void takeObstacles() {
    std::vector<Voxel> all;
    for (const PlacementObstacle& obstacle : options_.obstacles) {
      std::size_t counted = 0;
      for (const Voxel& v : obstacle.voxels) {
        const Voxel inside = options_.periodic ? options_.dims.wrap(v) : v;
        occupied_.set(options_.dims.index(inside));
        counted += counted_.contains(inside) ? 1 : 0;
      }
      all.insert(all.end(), obstacle.voxels.begin(), obstacle.voxels.end());
      if (options_.ownVoxels && !obstacle.own) continue;
      placedVoxels_ += counted;
      countedPerBin_[std::size_t(obstacle.bin)] +=
          double(counted) / double(std::max<std::size_t>(1, obstacle.voxelCount));
    }
    if (!all.empty()) field_.insert(all);
  }

  void startPhase(const PhasePlan& plan) {
    if (phase_) phase_->shapes.finish();
    phase_.emplace(plan, stats_, factory_, options_);
    if (plan.shrinks == 0) return;
    if (result_.particlesBeforeShrinking < 0)
      result_.particlesBeforeShrinking = int(result_.particles.size());
    result_.shrinkSteps = plan.shrinks;
    result_.smallestScale = std::pow(kShrink, plan.shrinks);
  }

  // Passes over the phase's bins, largest first, each placing the particles a bin misses, until
  // the fraction or the particle limit is reached (the reason is returned) or no bin fits any more.
  std::optional<std::string> fillPhase() {
    Phase& phase = *phase_;
    for (;;) {
      const std::size_t placedBefore = result_.particles.size();
      if (const std::optional<std::string> reason = pass(0)) return reason;
      // Every quota met to the nearest particle, and still volume to fill: rounding up places more
      // (some open bin is then below its rounded-up share, and nothing is held back), so every pass
      // places a particle or closes a bin, and the loop ends.
      phase.roundUp = result_.particles.size() == placedBefore;
      phase.passShare = 1;
      if (std::none_of(phase.open.begin(), phase.open.end(), [](bool open) { return open; }))
        return std::nullopt;
    }
  }

  // One pass over the phase's bins from the largest down to `smallest`, each placing the particles it
  // misses; the reason when the fraction or the particle limit is reached.
  std::optional<std::string> pass(int smallest) {
    Phase& phase = *phase_;
    for (int b = kBins - 1; b >= smallest; --b) {
      while (phase.open[std::size_t(b)] && !fractionReached() && !limitReached() && !overfills(b) &&
             countedPerBin_[std::size_t(b)] + (phase.roundUp ? 0.0 : kQuotaSlack) < quota(b))
        if (!attempt(b) && phase.pairs[std::size_t(b)].empty()) phase.open[std::size_t(b)] = false;
      if (fractionReached()) return "area fraction reached";
      if (limitReached()) return "particle limit reached";
    }
    return std::nullopt;
  }

  double fraction() const { return double(placedVoxels_) / double(fillVoxels_); }
  bool fractionReached() const { return double(placedVoxels_) >= targetVoxels_ - brickSlack(); }

  // A brick stops within half a particle of its share, above or below, as its last particle ends
  // past the share by half one on average: the bricks' last particles would otherwise overfill the
  // volume by half a particle each. Half the expected volume of the smallest open bin, which the
  // last particles come from.
  double brickSlack() const {
    if (!options_.ownVoxels || !phase_) return 0;
    for (int b = 0; b < kBins; ++b)
      if (phase_->open[std::size_t(b)]) return 0.5 * phase_->expectedVolume(b);
    return 0;
  }
  bool limitReached() const {
    return options_.maxParticles > 0 && int(result_.particles.size()) >= options_.maxParticles;
  }

  // A particle of bin b would overshoot the photo's fraction by more than it fills while a smaller bin
  // could still fill the rest: it waits (the volume must end as close to the fraction as it can).
  bool overfills(int b) const {
    const double missing = targetVoxels_ - double(placedVoxels_);
    if (phase_->roundUp || phase_->expectedVolume(b) <= 2 * missing)
      return false;  // after a pass that placed nothing, anything goes
    for (int i = 0; i < b; ++i)
      if (phase_->open[std::size_t(i)]) return true;
    return false;
  }

  // The count of bin b the volume should reach: with T particles in all, bin b holds share_b T, and T
  // is chosen so that the open bins' missing particles fill the missing volume. Rounded to the
  // nearest: rounding every bin up would overfill the volume by half a particle of each large bin
  // before the smallest bin, which comes last, gets its share. The first pass over the bins places
  // firstPassShare (0.85) of each; the second, with the volumes the shapes really took, the rest, so that
  // the luck of the shapes spreads over every bin instead of landing on the smallest alone.
  int quota(int b) const {
    const Phase& phase = *phase_;
    double missing = targetVoxels_ - double(placedVoxels_), perParticle = 0;
    for (int i = 0; i < kBins; ++i)
      if (phase.open[std::size_t(i)]) {
        missing += countedPerBin_[std::size_t(i)] * phase.expectedVolume(i);
        perParticle += phase.share[std::size_t(i)] * phase.expectedVolume(i);
      }
    const double share = phase.passShare * phase.share[std::size_t(b)] * missing / perParticle;
    return int(phase.roundUp ? std::ceil(share - 1e-9)
                             : std::floor(share + options_.quotaDither[std::size_t(b)]));
  }

  // Pairs of the bin in random order, by weight, until one is placed; false when none fits.
  // A pair that found no spot kFailuresToRetire times running is retired: the volume only fills, so
  // it would hardly find one later, and retrying it is where the time would go in a crowded volume.
  // The pairs are drawn from their own stream, so the pair after the one being tried is known, and
  // its shape is made meanwhile.
  bool attempt(int bin) {
    std::vector<WeightedPair>& pairs = phase_->pairs[std::size_t(bin)];
    if (pairs.empty()) return false;
    std::vector<int>& failures = phase_->failures[std::size_t(bin)];
    failures.resize(pairs.size(), 0);
    std::vector<std::size_t>& untried = untried_;
    untried.resize(pairs.size());
    std::iota(untried.begin(), untried.end(), 0);
    const auto drawUntried = [&] {
      const std::size_t pick = drawByWeight(pairs, untried, pairRng_);
      const std::size_t pair = untried[pick];
      untried.erase(untried.begin() + std::ptrdiff_t(pick));
      return pair;
    };
    bool placed = false;
    for (std::optional<std::size_t> pair = drawUntried(); pair && !placed;) {
      const std::optional<std::size_t> next = untried.empty() ? std::nullopt : std::optional(drawUntried());
      if (next)
        phase_->shapes.makeAhead({bin, pairs[*next].width, pairs[*next].height, pairs[*next].particlePhase});
      placed = tryPair(pairs[*pair], bin);
      if (placed) {
        failures[*pair] = 0;
      } else {
        ++failures[*pair];
        ++result_.rejectedPerBin[std::size_t(bin)];
      }
      pair = next;
    }
    for (std::size_t i = pairs.size(); i-- > 0;)
      if (failures[i] >= kFailuresToRetire) {
        phase_->shapes.forget({bin, pairs[i].width, pairs[i].height, pairs[i].particlePhase});
        pairs.erase(pairs.begin() + std::ptrdiff_t(i));
        failures.erase(failures.begin() + std::ptrdiff_t(i));
      }
    return placed;
  }

  bool tryPair(const WeightedPair& pair, int bin) {
    const placement::detail::ReadyShape shape =
        phase_->shapes.take({bin, pair.width, pair.height, pair.particlePhase});
    return !shape.fit.voxels.empty() && place(shape.fit, shape.size, bin);
  }

  // Uniform draws random spots that may hold the shape; best fit (paper 3.7), and uniform once its
  // random spots are spent, tries the smallest such spots first. Each is checked voxel by voxel.
  bool place(const placement::detail::FitShape& shape, const ParticleSize& size, int bin) {
    fieldUpdate_.wait();
    const float cap = field_.maxRadius();
    triedSpots_.clear();
    std::optional<Voxel> found;
    if (options_.arrangement == Arrangement::Uniform) {
      const float radius = std::min(cap, shape.innerRadius);
      found = firstFit(shape, ownSpots(field_.randomFit(radius, spotsAsked_, rng_)), radius);
    }
    for (int step = 0; step < kRadiusSteps && !found; ++step) {
      const float t = float(step) / float(kRadiusSteps - 1);
      const float radius = std::min(cap, shape.innerRadius + t * (shape.outerRadius - shape.innerRadius));
      std::vector<Voxel> spots = field_.bestFit(radius, spotsAsked_, rng_);
      if (spots.empty()) break;  // nothing this spacious, so nothing more spacious either
      found = firstFit(shape, ownSpots(std::move(spots)), radius);
    }
    for (const Voxel& spot : triedSpots_) tried_.clearWordOf(options_.dims.index(spot));
    if (found) commit(shape, *found, size, bin);
    return found.has_value();
  }

  // The field's spots inside PlacementOptions::spots, the first candidatesPerTry of them: the field
  // is asked for as many more as the volume is larger than that box, so that about as many are left.
  std::vector<Voxel> ownSpots(std::vector<Voxel> spots) const {
    if (!options_.spots) return spots;
    const Box& own = *options_.spots;
    spots.erase(std::remove_if(spots.begin(), spots.end(), [&](const Voxel& v) { return !own.contains(v); }),
                spots.end());
    if (spots.size() > std::size_t(options_.candidatesPerTry))
      spots.resize(std::size_t(options_.candidatesPerTry));
    return spots;
  }

  // The first of the spots, each valued at least `radius` by the field, where the shape fits.
  std::optional<Voxel> firstFit(const placement::detail::FitShape& shape, const std::vector<Voxel>& spots,
                                float radius) {
    for (const Voxel& spot : spots) {
      if (tried_.testAndSet(options_.dims.index(spot))) continue;
      triedSpots_.push_back(spot);
      // The field's spots hold at least `radius` less the slack: a free bound, where at() may be a costly
      // query.
      if (placement::detail::fitsAt(shape, spot, std::max(0.0f, radius - field_.slack()), occupied_,
                                    options_.dims, options_.periodic))
        return spot;
    }
    return std::nullopt;
  }

  void commit(const placement::detail::FitShape& shape, const Voxel& spot, const ParticleSize& size,
              int bin) {
    const int id = int(result_.particles.size()) + 1;
    const Voxel origin = placement::detail::originAt(shape, spot);
    volumeVoxels_.clear();
    const Dims idsDims = idsBox_.dims();
    std::size_t counted = 0;
    for (const Voxel& v : shape.voxels) {
      const Voxel w{origin.x + v.x, origin.y + v.y, origin.z + v.z};  // whole: the field wraps it itself
      const Voxel inside = options_.periodic ? options_.dims.wrap(w) : w;
      occupied_.set(options_.dims.index(inside));
      volumeVoxels_.push_back(w);
      if (idsBox_.contains(inside))
        result_
            .ids[idsDims.index(inside.x - idsBox_.lo.x, inside.y - idsBox_.lo.y, inside.z - idsBox_.lo.z)] =
            id;
      counted += counted_.contains(inside) ? 1 : 0;
    }
    // The field takes the particle while the next shape is made (place() waits for it): its
    // update and the shape's voxelization are the two largest costs of a try.
    fieldUpdate_.run([this] { field_.insert(volumeVoxels_); });
    result_.particles.push_back({id, origin, shape.dims, size.source, bin, shape.voxels.size(),
                                 phase_->plan.scale * factory_.phaseScale(factory_.phaseOf(size.source)),
                                 shape.pose});
    ++result_.placedPerBin[std::size_t(bin)];
    placedVoxels_ += counted;
    // A particle counts by its share inside the counted box: the margin's walls keep large particles
    // out of a wider band than small ones, and would otherwise crowd them into the box.
    countedPerBin_[std::size_t(bin)] += double(counted) / double(shape.voxels.size());
    // Placed shapes only: in a crowded volume the large shapes of a bin fail more often.
    ++phase_->made[std::size_t(bin)];
    phase_->madeVoxels[std::size_t(bin)] += double(shape.voxels.size());
    if (options_.progress && id % options_.progressEvery == 0) options_.progress(fraction(), id);
  }

  PlacementResult finish(const std::string& reason) {
    fieldUpdate_.wait();
    if (phase_) phase_->shapes.finish();
    result_.stopReason = reason;
    result_.volumeFraction = fraction();
    const auto placed = double(result_.particles.size());
    for (int b = 0; b < kBins; ++b)
      result_.volumeHistogram[std::size_t(b)] =
          placed > 0 ? result_.placedPerBin[std::size_t(b)] / placed : 0;
    if (options_.progress) options_.progress(result_.volumeFraction, int(result_.particles.size()));
    return std::move(result_);
  }

  const ExemplarStats& stats_;
  const ParticleFactory& factory_;
  SpaciousnessField& field_;
  const PlacementOptions& options_;
  Rng rng_;      ///< best-fit draws
  Rng pairRng_;  ///< the order pairs are tried in
  Box counted_;  ///< where the fraction and the particles per bin are counted
  Box idsBox_;   ///< where ids are kept
  int spotsAsked_ =
      spotsToAsk(options_);     ///< of the field per query: candidatesPerTry, more with a spots box
  std::size_t fillVoxels_ = 0;  ///< whose fraction placement reaches: the counted box's, or ownVoxels
  double targetVoxels_ = 0;
  std::size_t placedVoxels_ = 0;  ///< inside counted_
  std::array<double, kBins>
      countedPerBin_{};  ///< particles placed in every phase, each by its share inside counted_
  PlacementResult result_;
  placement::detail::VoxelBits occupied_;  ///< every particle's voxels, as bits: what fitsAt reads
  placement::detail::VoxelBits
      tried_;  ///< spots the current shape was tried at (their words are cleared after)
  std::vector<Voxel> triedSpots_;
  std::vector<std::size_t> untried_;  ///< attempt()'s pairs not tried yet
  std::optional<Phase> phase_;
  // Last, so that the task ends before what it reads is gone.
  std::vector<Voxel> volumeVoxels_;  ///< the last particle's, read by fieldUpdate_
  tbb::task_group fieldUpdate_;
};

}  // namespace

Arrangement parseArrangement(const std::string& name) {
  if (name == "best-fit") return Arrangement::BestFit;
  if (name == "uniform") return Arrangement::Uniform;
  throw OptionError("unknown arrangement '" + name + "': use best-fit or uniform");
}

const char* arrangementName(Arrangement arrangement) {
  return arrangement == Arrangement::BestFit ? "best-fit" : "uniform";
}

std::array<double, 10> firstPhaseBinShares(const ExemplarStats& stats, const PlacementOptions& options) {
  const BinPairs pairs = pairsPerBin(
      stats, phasePlans(options).front().photoShares ? std::vector<double>{} : options.particleWeights);
  std::array<double, kBins> shares{};
  double total = 0;
  for (int b = 0; b < kBins; ++b) total += shares[std::size_t(b)] = totalWeight(pairs[std::size_t(b)]);
  for (double& share : shares) share = total > 0 ? share / total : 0;
  return shares;
}

std::vector<PlacementPilot> placementPilots(const ExemplarStats& stats, const ParticleFactory& factory,
                                            const PlacementOptions& options) {
  std::vector<PlacementPilot> pilots;
  for (const PhasePlan& plan : phasePlans(options))
    pilots.push_back(
        pilotOf(plan, pairsPerBin(stats, plan.photoShares ? std::vector<double>{} : options.particleWeights),
                factory, options.seed));
  return pilots;
}

double targetFraction(const ExemplarStats& stats, const PlacementOptions& options) {
  return options.volumeFraction >= 0 ? options.volumeFraction : stats.areaFraction;
}

PlacementResult placeLargestFirst(const ExemplarStats& stats, const ParticleFactory& factory,
                                  SpaciousnessField& field, const PlacementOptions& options) {
  checkOptions(stats, options, field);
  return Placer(stats, factory, field, options).run();
}

}  // namespace solidtex
