// Paper 3.8: particles are made and placed one by one, largest area bin first, at best-fit spots of
// the spaciousness field, until the volume fraction reaches the photo's area fraction.
#include "placement/placeLargestFirst.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>

#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "common/Error.h"
#include "placement/detail/shapeFit.h"

namespace solidtex {
namespace {

constexpr int kBins = 10;
constexpr std::uint64_t kPlacementStream = 0x706c616365;  // "place"
// Radii asked of the field per shape, evenly from the spaciousness the shape needs at least (its
// inner radius) to the one with which it surely fits (its outer radius): the tightest spots are
// tried first, as best fit wants, but an irregular shape that fits none of them still finds room.
constexpr int kRadiusSteps = 4;
constexpr int kProgressEvery = 64;
constexpr int kFailuresToRetire = 8;
constexpr int kMinPilotShapes = 8, kMaxPilotShapes = 96;
constexpr double kFirstPassShare = 0.85;
constexpr double kShrink = 0.85;  // particles' size per shrink step once nothing fits
constexpr int kMaxShrinks = 3;
constexpr double kPilotPrecision = 0.03;  // standard error of the mean / mean
constexpr std::uint64_t kPilotStream = 0x70696c6f74;  // "pilot"
constexpr std::uint64_t kShapeStream = 0x7368617065;  // "shape"
constexpr std::uint64_t kPairStream = 0x7061697273;   // "pairs"

// A (width, height) box of the photo's particles and how often 3D particles take it.
struct WeightedPair {
  int width = 0, height = 0;
  double weight = 0;
};

using BinPairs = std::array<std::vector<WeightedPair>, kBins>;

// A particle made for a pair, ready to be tried at spots.
struct ReadyShape {
  ParticleSize size;
  detail::FitShape fit;  ///< no voxels when the shape came out empty
};

using ShapeKey = std::array<int, 3>;  // bin, width, height

// The (width, height) pairs of each area bin, from the particles the histogram counts (not cut by
// the photo's border; all when every one is), weighted by their particles' weights, or counted.
BinPairs pairsPerBin(const ExemplarStats& stats, const std::vector<double>& particleWeights) {
  std::array<std::map<std::pair<int, int>, double>, kBins> weights;
  for (std::size_t i : statisticalParticles(stats.particles)) {
    const Particle2D& p = stats.particles[i];
    const double weight = particleWeights.empty() ? 1.0 : particleWeights[i];
    if (p.box.width > 0 && p.box.height > 0 && weight > 0)
      weights[std::size_t(stats.histogram.binOf(p.area))][{p.box.width, p.box.height}] += weight;
  }
  BinPairs pairs;
  for (int b = 0; b < kBins; ++b)
    for (const auto& [size, weight] : weights[std::size_t(b)]) pairs[std::size_t(b)].push_back({size.first, size.second, weight});
  return pairs;
}

double totalWeight(const std::vector<WeightedPair>& pairs) {
  double total = 0;
  for (const WeightedPair& p : pairs) total += p.weight;
  return total;
}

// One of `candidates` (indices into pairs), drawn with probability proportional to its pair's weight;
// returns its position in `candidates`.
std::size_t drawByWeight(const std::vector<WeightedPair>& pairs, const std::vector<std::size_t>& candidates, Rng& rng) {
  double total = 0;
  for (const std::size_t c : candidates) total += pairs[c].weight;
  double draw = uniform01(rng) * total;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (draw < pairs[candidates[i]].weight) return i;
    draw -= pairs[candidates[i]].weight;
  }
  return candidates.size() - 1;
}

void checkOptions(const ExemplarStats& stats, const PlacementOptions& options, const SpaciousnessField& field) {
  const auto& w = options.particleWeights;
  if (!w.empty() && (w.size() != stats.particles.size() ||
                     std::any_of(w.begin(), w.end(), [](double v) { return !(v >= 0) || !std::isfinite(v); }) ||
                     !(std::accumulate(w.begin(), w.end(), 0.0) > 0)))
    throw InputError("placement: particle weights must be one non-negative number per photo particle, not all 0");
  if (!(options.voxelsPerPixel > 0) || !std::isfinite(options.voxelsPerPixel))
    throw InputError("placement: voxels per pixel must be positive, got " + std::to_string(options.voxelsPerPixel));
  if (!(options.sizeFactor > 0) || !std::isfinite(options.sizeFactor))
    throw InputError("placement: the size factor must be positive, got " + std::to_string(options.sizeFactor));
  if (options.maxParticles < 0)
    throw InputError("placement: the particle limit must not be negative, got " + std::to_string(options.maxParticles));
  if (options.candidatesPerTry < 1)
    throw InputError("placement: candidates per try must be at least 1, got " +
                     std::to_string(options.candidatesPerTry));
  if (options.counted) {
    const VolumeBox& c = *options.counted;
    if (c.dims.count() == 0 || !options.dims.contains(c.lo.x, c.lo.y, c.lo.z) ||
        !options.dims.contains(c.lo.x + c.dims.x - 1, c.lo.y + c.dims.y - 1, c.lo.z + c.dims.z - 1))
      throw std::invalid_argument("placement: the counted box is not inside the volume");
  }
  if (!(options.dims == field.dims()))
    throw std::invalid_argument("placement: the options' dims differ from the spaciousness field's");
}

class Placer {
public:
  Placer(const ExemplarStats& stats, const ParticleFactory& factory, SpaciousnessField& field,
         const PlacementOptions& options)
      : stats_(stats), factory_(factory), field_(field), options_(options),
        pairs_(pairsPerBin(stats, options.particleWeights)), rng_(deriveSeed(options.seed, kPlacementStream)),
        pairRng_(deriveSeed(options.seed, kPairStream)),
        occupied_(options.dims.count()), tried_(options.dims.count()) {
    const BinPairs photoPairs = pairsPerBin(stats, {});
    double total = 0, photoTotal = 0;
    for (int b = 0; b < kBins; ++b) {
      ratio_[std::size_t(b)] = totalWeight(pairs_[std::size_t(b)]);
      photoRatio_[std::size_t(b)] = totalWeight(photoPairs[std::size_t(b)]);
      total += ratio_[std::size_t(b)];
      photoTotal += photoRatio_[std::size_t(b)];
    }
    if (photoTotal == 0) throw InputError("placement: the photo has no particle to take sizes from");
    for (int b = 0; b < kBins; ++b) {
      ratio_[std::size_t(b)] /= total;
      photoRatio_[std::size_t(b)] /= photoTotal;
      open_[std::size_t(b)] = ratio_[std::size_t(b)] > 0;
    }
    scale_ = options.voxelsPerPixel * (options.particleWeights.empty() ? 1.0 : options.sizeFactor);
    startSizeEstimates();
    result_.dims = options.dims;
    result_.ids.assign(options.dims.count(), 0);
    counted_ = options.counted.value_or(VolumeBox{{0, 0, 0}, options.dims});
    targetVoxels_ = std::ceil(std::clamp(stats.areaFraction, 0.0, 1.0) * double(counted_.dims.count()));
  }

  // A task may still run when an exception leaves run(): wait for it, and drop its own error.
  ~Placer() {
    for (tbb::task_group* tasks : {&fieldUpdate_, &shapeAhead_}) {
      try {
        tasks->wait();
      } catch (...) {  // one exception is on its way already
      }
    }
  }

  PlacementResult run() {
    if (targetVoxels_ <= 0) return finish("the photo's area fraction is 0: nothing to place");
    for (;;) {
      const std::size_t placedBefore = result_.particles.size();
      for (int b = kBins - 1; b >= 0; --b) {
        while (open_[std::size_t(b)] && !fractionReached() && !limitReached() && !overfills(b) &&
               countedPerBin_[std::size_t(b)] < quota(b))
          if (!attempt(b) && pairs_[std::size_t(b)].empty()) open_[std::size_t(b)] = false;
        if (fractionReached()) return finish("area fraction reached");
        if (limitReached()) return finish("particle limit reached");
      }
      // Every quota met to the nearest particle, and still volume to fill: rounding up places more
      // (some open bin is then below its rounded-up share, and nothing is held back), so every pass
      // places a particle or closes a bin, and the loop ends.
      roundUp_ = result_.particles.size() == placedBefore;
      passShare_ = 1;
      if (std::none_of(open_.begin(), open_.end(), [](bool open) { return open; })) {
        if (topUpWithThePhotosShares() || shrinkTheRest()) continue;
        char reason[96];
        std::snprintf(reason, sizeof reason, "no bin fits any more (fraction %.3f of %.3f)", fraction(),
                      stats_.areaFraction);
        return finish(reason);
      }
    }
  }

private:
  // Shares other than the photo's can leave gaps only the photo's other sizes fit (a mix without
  // small particles jams early): once no bin of those shares fits, the photo's shares fill the rest.
  bool topUpWithThePhotosShares() {
    if (options_.particleWeights.empty() || phase_ > 0) return false;
    return restartAt(1, options_.voxelsPerPixel);
  }

  // A crowded photo (touching coins, dense gravel) can ask for more than random placement packs:
  // once nothing fits, the photo's shares are tried again smaller, kShrink at a time.
  bool shrinkTheRest() {
    const int shrinks = std::max(1, phase_);  // this one: phase k + 1 follows k shrinks
    if (shrinks > kMaxShrinks) return false;
    const int placed = int(result_.particles.size());
    if (!restartAt(shrinks + 1, options_.voxelsPerPixel * std::pow(kShrink, shrinks))) return false;
    if (result_.particlesBeforeShrinking < 0) result_.particlesBeforeShrinking = placed;
    result_.shrinkSteps = shrinks;
    result_.smallestScale = std::pow(kShrink, shrinks);
    return true;
  }

  // Every bin open again at the photo's shares, with particles of `scale` voxels per pixel and
  // their own random streams (phase).
  bool restartAt(int phase, double scale) {
    keepShapeMadeAhead();  // made at the earlier sizes: dropped below
    phase_ = phase;
    roundUp_ = false;
    ratio_ = photoRatio_;
    pairs_ = pairsPerBin(stats_, {});  // pairs retired at the larger sizes get a try at these
    shapesMade_.clear();
    shapesKept_.clear();
    for (auto& failures : failures_) failures.clear();
    scale_ = scale;
    startSizeEstimates();
    bool any = false;
    for (int b = 0; b < kBins; ++b) {
      open_[std::size_t(b)] = ratio_[std::size_t(b)] > 0 && !pairs_[std::size_t(b)].empty();
      any = any || open_[std::size_t(b)];
    }
    return any;
  }

  // Expected particle volumes per bin start from a few pilot shapes of the bin and follow the shapes
  // made since. The largest bins' counts are set before most of their shapes exist, and every voxel
  // they take beyond plan is taken from the smallest bin, placed last: the start must be right.
  void startSizeEstimates() {
    made_.fill(0);
    madeVoxels_.fill(0);
    tbb::parallel_for(0, kBins, [&](int b) {
      const auto& pairs = pairs_[std::size_t(b)];
      if (pairs.empty()) return;
      std::vector<std::size_t> all(pairs.size());
      std::iota(all.begin(), all.end(), 0);
      Rng rng(deriveSeed(options_.seed, kPilotStream + std::uint64_t(b) + std::uint64_t(phase_ * kBins)));
      // Until the mean is known to kPilotPrecision: a bin's sizes may span a factor of ten in volume.
      double sum = 0, sumOfSquares = 0;
      int n = 0;
      while (n < kMaxPilotShapes) {
        ++n;
        const WeightedPair& pair = pairs[all[drawByWeight(pairs, all, rng)]];
        const ParticleSize size = factory_.pickDepth(pair.width, pair.height, rng);
        const auto voxels = double(
            factory_.make(int(scaled(size.width)), int(scaled(size.height)), int(scaled(size.depth)), rng).voxelCount());
        sum += voxels;
        sumOfSquares += voxels * voxels;
        const double mean = sum / n, variance = std::max(0.0, sumOfSquares / n - mean * mean);
        if (n >= kMinPilotShapes && variance / n <= kPilotPrecision * kPilotPrecision * mean * mean) break;
      }
      made_[std::size_t(b)] = n;
      madeVoxels_[std::size_t(b)] = sum;
    });
  }

  double scaled(int pixels) const { return std::max(1.0, std::round(pixels * scale_)); }
  double fraction() const { return double(placedVoxels_) / double(counted_.dims.count()); }
  bool fractionReached() const { return double(placedVoxels_) >= targetVoxels_; }
  bool limitReached() const {
    return options_.maxParticles > 0 && int(result_.particles.size()) >= options_.maxParticles;
  }

  // A particle of bin b would overshoot the photo's fraction by more than it fills while a smaller bin
  // could still fill the rest: it waits (the volume must end as close to the fraction as it can).
  bool overfills(int b) const {
    const double missing = targetVoxels_ - double(placedVoxels_);
    if (roundUp_ || expectedVolume(b) <= 2 * missing) return false;  // after a pass that placed nothing, anything goes
    for (int i = 0; i < b; ++i)
      if (open_[std::size_t(i)]) return true;
    return false;
  }

  // Expected voxels of a particle of bin b: the mean of the shapes made for it so far.
  double expectedVolume(int b) const {
    return made_[std::size_t(b)] > 0 ? std::max(1.0, madeVoxels_[std::size_t(b)] / made_[std::size_t(b)]) : 1.0;
  }

  // The count of bin b the volume should reach: with T particles in all, bin b holds ratio_b T, and T
  // is chosen so that the open bins' missing particles fill the missing volume. Rounded to the
  // nearest: rounding every bin up would overfill the volume by half a particle of each large bin
  // before the smallest bin, which comes last, gets its share. The first pass over the bins places
  // kFirstPassShare of each; the second, with the volumes the shapes really took, the rest, so that
  // the luck of the shapes spreads over every bin instead of landing on the smallest alone.
  int quota(int b) const {
    double missing = targetVoxels_ - double(placedVoxels_), perParticle = 0;
    for (int i = 0; i < kBins; ++i)
      if (open_[std::size_t(i)]) {
        missing += countedPerBin_[std::size_t(i)] * expectedVolume(i);
        perParticle += ratio_[std::size_t(i)] * expectedVolume(i);
      }
    const double share = passShare_ * ratio_[std::size_t(b)] * missing / perParticle;
    return int(roundUp_ ? std::ceil(share - 1e-9) : std::round(share));
  }

  // Pairs of the bin in random order, by weight, until one is placed; false when none fits.
  // A pair that found no spot kFailuresToRetire times running is retired: the volume only fills, so
  // it would hardly find one later, and retrying it is where the time would go in a crowded volume.
  // The pairs are drawn from their own stream, so the pair after the one being tried is known, and
  // its shape is made meanwhile (kept for its next turn if this one fits).
  bool attempt(int bin) {
    std::vector<WeightedPair>& pairs = pairs_[std::size_t(bin)];
    if (pairs.empty()) return false;
    std::vector<int>& failures = failures_[std::size_t(bin)];
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
      if (next) makeAhead(pairs[*next], bin);
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
        shapesKept_.erase({bin, pairs[i].width, pairs[i].height});
        pairs.erase(pairs.begin() + std::ptrdiff_t(i));
        failures.erase(failures.begin() + std::ptrdiff_t(i));
      }
    return placed;
  }

  bool tryPair(const WeightedPair& pair, int bin) {
    const ReadyShape shape = takeShape({bin, pair.width, pair.height});
    return !shape.fit.voxels.empty() && place(shape.fit, shape.size, bin);
  }

  // The n-th shape of a pair comes from its own stream (seed, phase, bin, pair, n), whenever and
  // wherever it is made; a pair's shapes are taken in that order.
  ReadyShape makeShape(const ShapeKey& key, std::uint64_t n) const {
    Rng rng(deriveSeed(options_.seed, kShapeStream + std::uint64_t(phase_), key[0], key[1], key[2], n));
    ReadyShape shape;
    shape.size = factory_.pickDepth(key[1], key[2], rng);
    const VoxelShape voxels =
        factory_.make(int(scaled(shape.size.width)), int(scaled(shape.size.height)), int(scaled(shape.size.depth)), rng);
    if (voxels.voxelCount() > 0) shape.fit = detail::prepareShape(voxels);
    return shape;
  }

  // Starts making the pair's next shape on another thread, unless one is kept for it already.
  void makeAhead(const WeightedPair& pair, int bin) {
    keepShapeMadeAhead();
    const ShapeKey key{bin, pair.width, pair.height};
    if (shapesKept_.count(key)) return;
    ahead_.key = key;
    shapeAhead_.run([this, key, n = shapesMade_[key]++] { ahead_.shape = makeShape(key, n); });
  }

  void keepShapeMadeAhead() {
    shapeAhead_.wait();
    if (ahead_.key) shapesKept_.emplace(*ahead_.key, std::move(ahead_.shape));
    ahead_.key.reset();
  }

  ReadyShape takeShape(const ShapeKey& key) {
    if (ahead_.key == key) keepShapeMadeAhead();
    const auto kept = shapesKept_.find(key);
    if (kept == shapesKept_.end()) return makeShape(key, shapesMade_[key]++);
    ReadyShape shape = std::move(kept->second);
    shapesKept_.erase(kept);
    return shape;
  }

  // Uniform draws random spots that may hold the shape; best fit (paper 3.7), and uniform once its
  // random spots are spent, tries the smallest such spots first. Each is checked voxel by voxel.
  bool place(const detail::FitShape& shape, const ParticleSize& size, int bin) {
    fieldUpdate_.wait();
    const float cap = field_.maxRadius();
    triedSpots_.clear();
    std::optional<Voxel> found;
    if (options_.arrangement == Arrangement::Uniform)
      found = firstFit(shape, field_.randomFit(std::min(cap, shape.innerRadius), options_.candidatesPerTry, rng_),
                       std::min(cap, shape.innerRadius));
    for (int step = 0; step < kRadiusSteps && !found; ++step) {
      const float t = float(step) / float(kRadiusSteps - 1);
      const float radius = std::min(cap, shape.innerRadius + t * (shape.outerRadius - shape.innerRadius));
      const std::vector<Voxel> spots = field_.bestFit(radius, options_.candidatesPerTry, rng_);
      if (spots.empty()) break;  // nothing this spacious, so nothing more spacious either
      found = firstFit(shape, spots, radius);
    }
    for (const Voxel& spot : triedSpots_) tried_.clearWordOf(options_.dims.index(spot));
    if (found) commit(shape, *found, size, bin);
    return found.has_value();
  }

  // The first of the spots, each valued at least `radius` by the field, where the shape fits.
  std::optional<Voxel> firstFit(const detail::FitShape& shape, const std::vector<Voxel>& spots, float radius) {
    for (const Voxel& spot : spots) {
      if (tried_.testAndSet(options_.dims.index(spot))) continue;
      triedSpots_.push_back(spot);
      // The field's spots hold at least `radius` less the slack: a free bound, where at() may be a costly query.
      if (detail::fitsAt(shape, spot, std::max(0.0f, radius - field_.slack()), occupied_, options_.dims)) return spot;
    }
    return std::nullopt;
  }

  void commit(const detail::FitShape& shape, const Voxel& spot, const ParticleSize& size, int bin) {
    const int id = int(result_.particles.size()) + 1;
    const Voxel origin = detail::originAt(shape, spot);
    volumeVoxels_.clear();
    std::size_t counted = 0;
    for (const Voxel& v : shape.voxels) {
      const Voxel w{origin.x + v.x, origin.y + v.y, origin.z + v.z};
      result_.ids[options_.dims.index(w)] = id;
      occupied_.set(options_.dims.index(w));
      volumeVoxels_.push_back(w);
      counted += counted_.contains(w);
    }
    // The field takes the particle while the next shape is made (place() waits for it): its
    // update and the shape's voxelization are the two largest costs of a try.
    fieldUpdate_.run([this] { field_.insert(volumeVoxels_); });
    result_.particles.push_back({id, origin, shape.dims, size.source, bin, shape.voxels.size(), scale_});
    ++result_.placedPerBin[std::size_t(bin)];
    placedVoxels_ += counted;
    // A particle counts by its share inside the counted box: the margin's walls keep large particles
    // out of a wider band than small ones, and would otherwise crowd them into the box.
    countedPerBin_[std::size_t(bin)] += double(counted) / double(shape.voxels.size());
    // Placed shapes only: in a crowded volume the large shapes of a bin fail more often.
    ++made_[std::size_t(bin)];
    madeVoxels_[std::size_t(bin)] += double(shape.voxels.size());
    if (options_.progress && id % kProgressEvery == 0) options_.progress(fraction(), id);
  }

  PlacementResult finish(const std::string& reason) {
    fieldUpdate_.wait();
    shapeAhead_.wait();
    result_.stopReason = reason;
    result_.volumeFraction = fraction();
    const auto placed = double(result_.particles.size());
    for (int b = 0; b < kBins; ++b)
      result_.volumeHistogram[std::size_t(b)] = placed > 0 ? result_.placedPerBin[std::size_t(b)] / placed : 0;
    if (options_.progress) options_.progress(result_.volumeFraction, int(result_.particles.size()));
    return std::move(result_);
  }

  const ExemplarStats& stats_;
  const ParticleFactory& factory_;
  SpaciousnessField& field_;
  const PlacementOptions& options_;
  BinPairs pairs_;
  std::map<ShapeKey, std::uint64_t> shapesMade_;  ///< shapes made (or being made) per pair
  std::array<std::vector<int>, kBins> failures_;  ///< per pair of pairs_, tries that found no spot in a row
  Rng rng_;      ///< best-fit draws
  Rng pairRng_;  ///< the order pairs are tried in
  std::array<double, kBins> ratio_{}, photoRatio_{}, madeVoxels_{};
  std::array<int, kBins> made_{};
  std::array<bool, kBins> open_{};
  int phase_ = 0;  ///< 0: the sizing's shares; 1: topped up with the photo's; 2 on: shrunk phase_ - 1 times
  bool roundUp_ = false;
  double passShare_ = kFirstPassShare;
  double scale_ = 1;  ///< voxels per photo pixel of the particles made now
  VolumeBox counted_;            ///< where the fraction and the particles per bin are counted
  std::array<double, kBins> countedPerBin_{};  ///< particles placed, each by its share inside counted_
  double targetVoxels_ = 0;
  std::size_t placedVoxels_ = 0;  ///< inside counted_
  PlacementResult result_;
  detail::VoxelBits occupied_;  ///< result_.ids != 0, as bits: what fitsAt reads, 1/32 of the ids' size
  detail::VoxelBits tried_;  ///< spots the current shape was tried at (their words are cleared after)
  std::vector<Voxel> triedSpots_;
  std::vector<std::size_t> untried_;  ///< attempt()'s pairs not tried yet
  // Last, so that the tasks end before what they read is gone.
  std::map<ShapeKey, ReadyShape> shapesKept_;  ///< made ahead, not taken yet
  struct {
    std::optional<ShapeKey> key;
    ReadyShape shape;
  } ahead_;  ///< the shape shapeAhead_ makes, for the pair `key`
  tbb::task_group shapeAhead_;
  std::vector<Voxel> volumeVoxels_;  ///< the last particle's, read by fieldUpdate_
  tbb::task_group fieldUpdate_;
};

} // namespace

Arrangement parseArrangement(const std::string& name) {
  if (name == "best-fit") return Arrangement::BestFit;
  if (name == "uniform") return Arrangement::Uniform;
  throw InputError("unknown arrangement '" + name + "': use best-fit or uniform");
}

const char* arrangementName(Arrangement arrangement) {
  return arrangement == Arrangement::BestFit ? "best-fit" : "uniform";
}

PlacementResult placeLargestFirst(const ExemplarStats& stats, const ParticleFactory& factory,
                                  SpaciousnessField& field, const PlacementOptions& options) {
  checkOptions(stats, options, field);
  return Placer(stats, factory, field, options).run();
}

} // namespace solidtex
