#include "placement/placeInBricks.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include <tbb/parallel_for.h>

#include "common/Error.h"
#include "common/Random.h"
#include "common/bricksOf.h"
#include "common/failureText.h"
#include "common/secondsSince.h"

namespace solidtex {
namespace {

constexpr int kColours = 8;
constexpr std::uint64_t kBrickStream = 0x627269636b;  // "brick"

Box shifted(const Box& b, const Voxel& by) {
  return {{b.lo.x + by.x, b.lo.y + by.y, b.lo.z + by.z}, {b.hi.x + by.x, b.hi.y + by.y, b.hi.z + by.z}};
}

Voxel negated(const Voxel& v) { return {-v.x, -v.y, -v.z}; }

Box intersection(const Box& a, const Box& b) {
  return {{std::max(a.lo.x, b.lo.x), std::max(a.lo.y, b.lo.y), std::max(a.lo.z, b.lo.z)},
          {std::min(a.hi.x, b.hi.x), std::min(a.hi.y, b.hi.y), std::min(a.hi.z, b.hi.z)}};
}

// One brick's boxes in the placed volume's coordinates.
struct BrickPlan {
  Box brick;   ///< what it counts
  Box spots;   ///< where its particles are centred: the brick, and the margin beyond the counted box's faces
  Box window;  ///< what it sees and fills: the spots and a halo, inside the volume
  int colour = 0;
};

// In a periodic volume windows run past its faces (their voxels wrap), and spots stay in the brick.
std::vector<BrickPlan> planBricks(const Dims& placed, const Box& counted, int edge, int halo, bool periodic) {
  std::vector<BrickPlan> plans;
  for (const Box& local : bricksOf(counted.dims(), edge)) {
    BrickPlan plan;
    plan.brick = shifted(local, counted.lo);
    plan.spots = plan.brick;
    const int los[3] = {counted.lo.x, counted.lo.y, counted.lo.z},
              his[3] = {counted.hi.x, counted.hi.y, counted.hi.z};
    const int ends[3] = {placed.x, placed.y, placed.z};
    int* spotLo[3] = {&plan.spots.lo.x, &plan.spots.lo.y, &plan.spots.lo.z};
    int* spotHi[3] = {&plan.spots.hi.x, &plan.spots.hi.y, &plan.spots.hi.z};
    int* windowLo[3] = {&plan.window.lo.x, &plan.window.lo.y, &plan.window.lo.z};
    int* windowHi[3] = {&plan.window.hi.x, &plan.window.hi.y, &plan.window.hi.z};
    for (int a = 0; a < 3; ++a) {
      if (periodic) {
        *windowLo[a] = *spotLo[a] - halo;
        *windowHi[a] = *spotHi[a] + halo;
        continue;
      }
      if (*spotLo[a] == los[a]) *spotLo[a] = 0;
      if (*spotHi[a] == his[a]) *spotHi[a] = ends[a];
      *windowLo[a] = std::max(0, *spotLo[a] - halo);
      *windowHi[a] = std::min(ends[a], *spotHi[a] + halo);
    }
    plan.colour = (local.lo.x / edge & 1) + 2 * (local.lo.y / edge & 1) + 4 * (local.lo.z / edge & 1);
    plans.push_back(plan);
  }
  return plans;
}

// The particles (ids into `particles`) that have voxels in the window, with those voxels in the
// window's coordinates, in the order of their ids; those of brick `brick` (brickOf, per particle)
// are its own.
std::vector<PlacementObstacle> obstaclesIn(const Box& window, const Dims& placed,
                                           const std::vector<std::int32_t>& owner,
                                           const std::vector<PlacedParticle>& particles,
                                           const std::vector<std::uint32_t>& brickOf, std::size_t brick) {
  std::map<std::int32_t, PlacementObstacle> byId;
  for (int k = window.lo.z; k < window.hi.z; ++k)
    for (int j = window.lo.y; j < window.hi.y; ++j)
      for (int i = window.lo.x; i < window.hi.x; ++i)
        if (const std::int32_t id = owner[placed.index(placed.wrap({i, j, k}))])
          byId[id].voxels.push_back({i - window.lo.x, j - window.lo.y, k - window.lo.z});
  std::vector<PlacementObstacle> obstacles;
  obstacles.reserve(byId.size());
  for (auto& [id, obstacle] : byId) {
    const PlacedParticle& p = particles[std::size_t(id) - 1];
    obstacle.bin = p.bin;
    obstacle.voxelCount = p.voxelCount;
    obstacle.own = brickOf[std::size_t(id) - 1] == brick;
    obstacles.push_back(std::move(obstacle));
  }
  return obstacles;
}

// One brick's placement, its ids as the (window index, id) of its particles' voxels.
struct BrickOutcome {
  std::size_t brick = 0;
  int rank = 0;
  double seconds = 0;
  PlacementResult placement;  ///< without ids
  std::vector<std::pair<std::uint32_t, std::int32_t>> taken;
};

// What every brick of a round shares: the bins it places, its number (for the bricks' seeds), the
// pilots of the one schedule.
struct Round {
  std::optional<int> firstPassDownTo;  ///< none: the rest of the placement
  double firstPassShare = 0.85;        ///< of the quota of bin firstPassDownTo, reached by this round
  std::uint64_t index = 0;
  const std::vector<PlacementPilot>* pilots = nullptr;
};

// Brick i's quota dithers: the golden-ratio sequence, offset per bin, so that the bricks' values of
// a bin spread evenly over [0, 1) and their rounded quotas add up to about the whole volume's.
std::array<double, 10> quotaDitherOf(std::size_t brick) {
  std::array<double, 10> dither{};
  for (std::size_t b = 0; b < dither.size(); ++b) {
    const double value = 0.5 + 0.6180339887498949 * double(brick) + 0.4142135623730950 * double(b);
    dither[b] = value - std::floor(value);
  }
  return dither;
}

BrickOutcome placeBrick(const ExemplarStats& stats, const ParticleFactory& factory,
                        const BrickedPlacementOptions& options, const Round& round, const BrickPlan& plan,
                        std::size_t index, const Dims& placed, const Box& counted,
                        const std::vector<std::int32_t>& owner, const std::vector<PlacedParticle>& particles,
                        const std::vector<std::uint32_t>& brickOf) {
  const auto start = std::chrono::steady_clock::now();
  PlacementOptions brick = options.placement;
  brick.firstPassDownTo = round.firstPassDownTo;
  brick.firstPassShare = round.firstPassShare;
  brick.pilots = *round.pilots;
  const Voxel toWindow = negated(plan.window.lo);
  brick.dims = plan.window.dims();
  // A brick fills its share: its own particles' voxels inside the counted box, wherever they are,
  // make its fraction, so that a neighbour's particles reaching into it do not fill it twice.
  brick.counted = options.placement.periodic ? Box::of(brick.dims)
                                             : shifted(intersection(counted, plan.window), toWindow);
  brick.periodic = false;  // the window is a box of the torus, walled
  brick.ownVoxels = plan.brick.dims().count();
  brick.quotaDither = quotaDitherOf(index);
  brick.spots = shifted(plan.spots, toWindow);
  brick.idsEverywhere = true;
  brick.seed = deriveSeed(options.placement.seed, kBrickStream, index, round.index);
  brick.progress = {};
  brick.obstacles = obstaclesIn(plan.window, placed, owner, particles, brickOf, index);
  auto field = makeSpaciousnessField(options.placer, brick.dims, options.radiusCap, false);
  BrickOutcome outcome{index, options.team.rank, 0, placeLargestFirst(stats, factory, *field, brick), {}};
  field.reset();
  std::vector<std::int32_t> ids = std::move(outcome.placement.ids);
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (ids[i] != 0) outcome.taken.emplace_back(std::uint32_t(i), ids[i]);
  outcome.seconds = secondsSince(start);
  return outcome;
}

// Plain values packed in the machine's own byte order: the processes are one build on one kind of
// machine.
class Packer {
public:
  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  void put(const std::string& text) {
    put(std::uint64_t(text.size()));
    bytes_ += text;
  }
  std::string take() { return std::move(bytes_); }

private:
  std::string bytes_;
};

class Unpacker {
public:
  explicit Unpacker(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    if (at_ + sizeof(T) > bytes_.size()) throw std::runtime_error("placeInBricks: a brick's bytes end early");
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof value);
    at_ += sizeof value;
    return value;
  }
  std::string text() {
    const auto length = get<std::uint64_t>();
    if (at_ + length > bytes_.size()) throw std::runtime_error("placeInBricks: a brick's bytes end early");
    std::string out = bytes_.substr(at_, length);
    at_ += length;
    return out;
  }
  bool done() const { return at_ == bytes_.size(); }

private:
  const std::string& bytes_;
  std::size_t at_ = 0;
};

void pack(Packer& out, const PlacedParticle& p) {
  out.put(p.id);
  out.put(p.origin);
  out.put(p.box);
  out.put(p.source);
  out.put(p.bin);
  out.put(std::uint64_t(p.voxelCount));
  out.put(p.voxelsPerPixel);
  out.put(p.pose.hull);
  for (int i = 0; i < 9; ++i) out.put(p.pose.linear.data()[i]);
  for (int i = 0; i < 3; ++i) out.put(p.pose.offset.data()[i]);
}

PlacedParticle unpackParticle(Unpacker& in) {
  PlacedParticle p;
  p.id = in.get<int>();
  p.origin = in.get<Voxel>();
  p.box = in.get<Dims>();
  p.source = in.get<int>();
  p.bin = in.get<int>();
  p.voxelCount = std::size_t(in.get<std::uint64_t>());
  p.voxelsPerPixel = in.get<double>();
  p.pose.hull = in.get<int>();
  for (int i = 0; i < 9; ++i) p.pose.linear.data()[i] = in.get<double>();
  for (int i = 0; i < 3; ++i) p.pose.offset.data()[i] = in.get<double>();
  return p;
}

// A process's bricks of one colour, or its failure (failureText) when one failed.
std::string pack(const std::vector<BrickOutcome>& outcomes, const std::string& failure) {
  Packer out;
  out.put(failure);
  out.put(std::uint64_t(failure.empty() ? outcomes.size() : 0));
  if (!failure.empty()) return out.take();
  for (const BrickOutcome& o : outcomes) {
    const PlacementResult& r = o.placement;
    out.put(std::uint64_t(o.brick));
    out.put(o.rank);
    out.put(o.seconds);
    out.put(r.placedPerBin);
    out.put(r.rejectedPerBin);
    out.put(r.shrinkSteps);
    out.put(r.smallestScale);
    out.put(r.particlesBeforeShrinking);
    out.put(r.stopReason);
    out.put(std::uint64_t(r.particles.size()));
    for (const PlacedParticle& p : r.particles) pack(out, p);
    out.put(std::uint64_t(o.taken.size()));
    for (const auto& [index, id] : o.taken) {
      out.put(index);
      out.put(id);
    }
  }
  return out.take();
}

std::vector<BrickOutcome> unpackOutcomes(const std::string& bytes, std::string& failure) {
  Unpacker in(bytes);
  failure = in.text();
  std::vector<BrickOutcome> outcomes(std::size_t(in.get<std::uint64_t>()));
  for (BrickOutcome& o : outcomes) {
    PlacementResult& r = o.placement;
    o.brick = std::size_t(in.get<std::uint64_t>());
    o.rank = in.get<int>();
    o.seconds = in.get<double>();
    r.placedPerBin = in.get<std::array<int, 10>>();
    r.rejectedPerBin = in.get<std::array<int, 10>>();
    r.shrinkSteps = in.get<int>();
    r.smallestScale = in.get<double>();
    r.particlesBeforeShrinking = in.get<int>();
    r.stopReason = in.text();
    r.particles.resize(std::size_t(in.get<std::uint64_t>()));
    for (PlacedParticle& p : r.particles) p = unpackParticle(in);
    o.taken.resize(std::size_t(in.get<std::uint64_t>()));
    for (auto& [index, id] : o.taken) {
      index = in.get<std::uint32_t>();
      id = in.get<std::int32_t>();
    }
  }
  if (!in.done()) throw std::runtime_error("placeInBricks: a process's bricks have bytes left over");
  return outcomes;
}

void checkBrickedOptions(const BrickedPlacementOptions& options, int halo) {
  const PlacementOptions& p = options.placement;
  if (p.periodic) {
    const int sides[3] = {p.dims.x, p.dims.y, p.dims.z};
    for (const int side : sides)
      if (side % options.brickEdge != 0 || (side / options.brickEdge) % 2 != 0)
        throw InputError(
            "in a periodic volume bricks must cut every side into an even number, as their colours "
            "alternate around it: bricks of " +
            std::to_string(options.brickEdge) + " do not cut " + std::to_string(side));
  }
  if (p.maxParticles > 0)
    throw std::invalid_argument("placeInBricks: a particle limit has no meaning per brick");
  if (!p.obstacles.empty() || p.spots || p.idsEverywhere)
    throw std::invalid_argument("placeInBricks: obstacles, spots and ids are set per brick");
  if (options.brickEdge < 2 * halo)
    throw InputError("bricks of " + std::to_string(options.brickEdge) +
                     " voxels are narrower than twice the particles' reach (" + std::to_string(halo) +
                     "): use --bricks " + std::to_string(2 * halo) + " or more");
}

// "area fraction reached (6 of 8 bricks); no bin fits any more (2 of 8 bricks)": the bricks' reasons
// without their figures.
std::string stopReasons(const std::vector<BrickPlacement>& bricks) {
  std::map<std::string, int> counts;
  for (const BrickPlacement& b : bricks) ++counts[b.stopReason.substr(0, b.stopReason.find(" ("))];
  std::string text;
  for (const auto& [reason, count] : counts)
    text += (text.empty() ? "" : "; ") + reason + " (" + std::to_string(count) + " of " +
            std::to_string(bricks.size()) + " bricks)";
  return text;
}

// The rounds: the first pass of each bin that has particles, largest first, then the rest. A bin
// that holds much of the volume goes in several rounds, a part of its quota each: the bricks first
// in a round's order fill freely and those last fit around them, and the order changes by round.
std::vector<Round> roundsOf(const std::array<double, 10>& shares, const PlacementPilot& pilot) {
  constexpr double kFirstPass = 0.85, kVolumePerRound = 0.2;
  constexpr int kMostRounds = 4;
  std::array<double, 10> volume{};
  double total = 0;
  for (std::size_t b = 0; b < volume.size(); ++b) {
    if (pilot.shapes[b] > 0) volume[b] = shares[b] * pilot.voxels[b] / pilot.shapes[b];
    total += volume[b];
  }
  std::vector<Round> rounds;
  for (int b = int(volume.size()) - 1; b >= 0; --b) {
    if (pilot.shapes[std::size_t(b)] == 0) continue;
    const double share = total > 0 ? volume[std::size_t(b)] / total : 0;
    const int parts = std::clamp(int(std::ceil(share / kVolumePerRound)), 1, kMostRounds);
    for (int part = 1; part <= parts; ++part) rounds.push_back({b, kFirstPass * part / parts});
  }
  rounds.push_back({});
  return rounds;
}

// The bricks `ofColour` (indices into plans) dealt to this process, placed in parallel; with other
// processes, every process's, exchanged. In the order of ofColour.
std::vector<BrickOutcome> placeColour(const ExemplarStats& stats, const ParticleFactory& factory,
                                      const BrickedPlacementOptions& options, const Round& round,
                                      const std::vector<BrickPlan>& plans,
                                      const std::vector<std::size_t>& ofColour, const Dims& placed,
                                      const Box& counted, const std::vector<std::int32_t>& owner,
                                      const std::vector<PlacedParticle>& particles,
                                      const std::vector<std::uint32_t>& brickOf,
                                      std::size_t& bytesExchanged) {
  const BrickTeam& team = options.team;
  std::vector<std::size_t> mine;
  for (std::size_t i = 0; i < ofColour.size(); ++i)
    if (int(i % std::size_t(team.size)) == team.rank) mine.push_back(ofColour[i]);
  std::vector<BrickOutcome> outcomes(mine.size());
  std::vector<std::exception_ptr> failures(mine.size());
  tbb::parallel_for(std::size_t(0), mine.size(), [&](std::size_t i) {
    try {
      outcomes[i] = placeBrick(stats, factory, options, round, plans[mine[i]], mine[i], placed, counted,
                               owner, particles, brickOf);
    } catch (...) {
      failures[i] = std::current_exception();
    }
  });
  const auto failed = std::find_if(failures.begin(), failures.end(), [](const auto& f) { return bool(f); });
  if (team.size == 1) {
    if (failed != failures.end()) std::rethrow_exception(*failed);
    return outcomes;
  }
  // A process whose brick failed still sends, so that none waits for it; all then throw the first.
  const std::vector<std::string> parts =
      team.allGather(pack(outcomes, failed != failures.end() ? failureText(*failed) : std::string()));
  std::vector<BrickOutcome> all;
  std::string failure;
  for (const std::string& part : parts) {
    bytesExchanged += part.size();
    std::string partFailure;
    for (BrickOutcome& o : unpackOutcomes(part, partFailure)) all.push_back(std::move(o));
    if (failure.empty()) failure = partFailure;
  }
  if (!failure.empty()) throwFailureText(failure);
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.brick < b.brick; });
  return all;
}

}  // namespace

int brickHalo(float radiusCap) { return int(std::ceil(double(radiusCap))); }

BrickedPlacementResult placeInBricks(const ExemplarStats& stats, const ParticleFactory& factory,
                                     const BrickedPlacementOptions& options) {
  BrickedPlacementResult out;
  out.halo = brickHalo(options.radiusCap);
  checkBrickedOptions(options, out.halo);
  const Dims placed = options.placement.dims;
  const Box counted = options.placement.counted.value_or(Box::of(placed));
  const std::vector<BrickPlan> plans =
      planBricks(placed, counted, options.brickEdge, out.halo, options.placement.periodic);

  PlacementResult& result = out.placement;
  std::vector<std::int32_t> owner(placed.count(), 0);  // particle ids over the whole placed volume
  std::vector<PlacedParticle>& particles = result.particles;
  std::vector<std::uint32_t> brickOf;  // per particle, the brick whose spot it was placed from
  out.bricks.resize(plans.size());
  std::size_t countedVoxels = 0;
  int shrunk = 0, beforeShrinking = 0;
  result.smallestScale = 1;
  // Rounds go bin by bin through every brick, as the whole volume's placement goes largest bin
  // first: the first pass of each bin in turn, then the rest of the placement. Bricks placed in one
  // go would pack their faces before their neighbours' large particles come, and show as seams.
  const std::vector<PlacementPilot> pilots = placementPilots(stats, factory, options.placement);
  std::vector<Round> rounds = roundsOf(firstPhaseBinShares(stats, options.placement), pilots.front());
  out.colourSeconds.assign(kColours, 0);
  out.rounds = int(rounds.size());
  for (std::size_t r = 0; r < rounds.size(); ++r) {
    Round& round = rounds[r];
    round.index = r;
    round.pilots = &pilots;
    // The colours' order changes from round to round (colour bits flipped by the round's): a brick
    // that goes before its neighbour in one round goes after it in another, and neither side of a
    // face is always the one packed first.
    for (int turn = 0; turn < kColours; ++turn) {
      const int colour = turn ^ int(r % kColours);
      std::vector<std::size_t> ofColour;
      for (std::size_t b = 0; b < plans.size(); ++b)
        if (plans[b].colour == colour) ofColour.push_back(b);
      const auto start = std::chrono::steady_clock::now();
      std::vector<BrickOutcome> outcomes =
          placeColour(stats, factory, options, round, plans, ofColour, placed, counted, owner, particles,
                      brickOf, out.bytesExchanged);
      out.colourSeconds[std::size_t(colour)] += secondsSince(start);
      for (BrickOutcome& outcome : outcomes) {  // joined in brick order: ids do not depend on threads
        const BrickPlan& plan = plans[outcome.brick];
        const PlacementResult& brick = outcome.placement;
        const auto offset = std::int32_t(particles.size());
        for (PlacedParticle p : brick.particles) {
          brickOf.push_back(std::uint32_t(outcome.brick));
          p.id += offset;
          p.origin = {p.origin.x + plan.window.lo.x, p.origin.y + plan.window.lo.y,
                      p.origin.z + plan.window.lo.z};
          particles.push_back(p);
        }
        const Dims window = plan.window.dims();
        for (const auto& [index, id] : outcome.taken) {
          const Voxel w = window.voxel(index);
          const Voxel v{w.x + plan.window.lo.x, w.y + plan.window.lo.y, w.z + plan.window.lo.z};
          const Voxel inside = placed.wrap(v);
          owner[placed.index(inside)] = id + offset;
          countedVoxels += counted.contains(inside) ? 1 : 0;
        }
        for (std::size_t b = 0; b < result.placedPerBin.size(); ++b) {
          result.placedPerBin[b] += brick.placedPerBin[b];
          result.rejectedPerBin[b] += brick.rejectedPerBin[b];
        }
        const bool didShrink = brick.particlesBeforeShrinking >= 0;
        shrunk = std::max(shrunk, brick.shrinkSteps);
        result.smallestScale = std::min(result.smallestScale, brick.smallestScale);
        beforeShrinking += didShrink ? brick.particlesBeforeShrinking : int(brick.particles.size());
        BrickPlacement& summary = out.bricks[outcome.brick];
        summary.brick = shifted(plan.brick, negated(counted.lo));
        summary.colour = colour;
        summary.rank = outcome.rank;
        summary.particles += int(brick.particles.size());
        summary.seconds += outcome.seconds;
        summary.stopReason = brick.stopReason;
        if (options.placement.progress)
          options.placement.progress(double(countedVoxels) / double(counted.dims().count()),
                                     int(particles.size()));
      }
    }
  }

  for (std::size_t b = 0; b < plans.size(); ++b) {
    const Box& box = plans[b].brick;
    std::size_t taken = 0;
    for (int k = box.lo.z; k < box.hi.z; ++k)
      for (int j = box.lo.y; j < box.hi.y; ++j)
        for (int i = box.lo.x; i < box.hi.x; ++i) taken += owner[placed.index(i, j, k)] != 0 ? 1 : 0;
    out.bricks[b].volumeFraction = double(taken) / double(box.dims().count());
  }
  result.dims = placed;
  result.periodic = options.placement.periodic;
  result.counted = counted;
  if (counted == Box::of(placed)) {
    result.ids = std::move(owner);
  } else {
    const Dims c = counted.dims();
    result.ids.resize(c.count());
    for (int k = 0; k < c.z; ++k)
      for (int j = 0; j < c.y; ++j)
        for (int i = 0; i < c.x; ++i)
          result.ids[c.index(i, j, k)] =
              owner[placed.index(i + counted.lo.x, j + counted.lo.y, k + counted.lo.z)];
  }
  result.volumeFraction = double(countedVoxels) / double(counted.dims().count());
  const double total = double(particles.size());
  for (std::size_t b = 0; b < result.volumeHistogram.size(); ++b)
    result.volumeHistogram[b] = total > 0 ? result.placedPerBin[b] / total : 0;
  result.stopReason = stopReasons(out.bricks);
  result.shrinkSteps = shrunk;
  result.particlesBeforeShrinking = shrunk > 0 ? beforeShrinking : -1;
  return out;
}

}  // namespace solidtex
