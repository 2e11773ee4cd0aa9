#include "synthesis/synthesizeFromVolume.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include <tbb/parallel_for.h>

#include "common/Error.h"
#include "common/Random.h"
#include "common/ThreadLimit.h"
#include "common/secondsSince.h"
#include "synthesis/detail/AppearanceSpace.h"

namespace solidtex {
namespace {

using synthesis::detail::AppearanceLevel;
using synthesis::detail::ExemplarDomain;
using Coord = std::array<int, 3>;  // a domain voxel
using Frame = Eigen::Matrix3f;     // columns: the output directions of the exemplar axes

int floorMod(int v, int n) {
  v %= n;
  return v < 0 ? v + n : v;
}

// Synthesis works on coordinates: each voxel of a level holds the domain voxel it copies.
struct CoordinateGrid {
  Voxel lo;  // the window's first voxel, in the level's coordinates
  Dims dims;
  // Axes a periodic level's window covers whole (then lo is 0): reads past its faces wrap.
  std::array<bool, 3> wraps{};
  std::vector<std::array<std::int16_t, 3>> coords;

  Voxel wrapped(int x, int y, int z) const {
    return {wraps[0] ? floorMod(x, dims.x) : x, wraps[1] ? floorMod(y, dims.y) : y,
            wraps[2] ? floorMod(z, dims.z) : z};
  }
  std::size_t index(int x, int y, int z) const {
    const Voxel w = wrapped(x, y, z);
    return dims.index(w.x - lo.x, w.y - lo.y, w.z - lo.z);
  }
  Coord at(int x, int y, int z) const {
    const auto& c = coords[index(x, y, z)];
    return {c[0], c[1], c[2]};
  }
  // A read outside the window continues the nearest voxel inside it coherently: that voxel's
  // coordinate moved by the exemplar step the frame maps there (`inverse` = frame transposed,
  // times the spacing). Repeating the edge voxel instead would distort the neighbourhoods along the
  // output's faces. The rule is the same at a volume's faces for a region and for the whole volume.
  // Wrapping axes have no faces.
  Coord extendedAt(int x, int y, int z, const Frame& inverse, float h) const {
    const Voxel w = wrapped(x, y, z);
    x = w.x, y = w.y, z = w.z;
    const Voxel c{std::clamp(x, lo.x, lo.x + dims.x - 1), std::clamp(y, lo.y, lo.y + dims.y - 1),
                  std::clamp(z, lo.z, lo.z + dims.z - 1)};
    Coord s = at(c.x, c.y, c.z);
    if (c.x == x && c.y == y && c.z == z) return s;
    const Eigen::Vector3f step =
        h * (inverse * Eigen::Vector3f(float(x - c.x), float(y - c.y), float(z - c.z)));
    for (int a = 0; a < 3; ++a) s[std::size_t(a)] += int(std::lround(step[a]));
    return s;
  }
  void set(std::size_t i, const Coord& c) {
    coords[i] = {std::int16_t(c[0]), std::int16_t(c[1]), std::int16_t(c[2])};
  }
};

// The level plan: spacing, level dims and the window each level must synthesise.
struct LevelPlan {
  int spacing = 1;
  Dims dims;                    // the whole level
  Box window;                   // what is synthesised; on a periodic level it may run past the faces
  std::array<bool, 3> wraps{};  // axes whose window is the whole periodic level
  bool periodic = false;
  int appearance = -1;  // index into the appearance levels; -1 = not corrected

  // The level voxel a window voxel stands for (a periodic window's coordinates run past the faces).
  Voxel onLevel(int x, int y, int z) const {
    if (!periodic) return {x, y, z};
    return {floorMod(x, dims.x), floorMod(y, dims.y), floorMod(z, dims.z)};
  }
};

int ceilDiv(int a, int b) { return (a + b - 1) / b; }

// Halvings from the output to the coarsest level. Without --periodic the coarsest level is one voxel
// (a level covers ceil(side / h) voxels). A periodic level must be tiled exactly by the next finer
// one, so its pyramid stops where a side would stop being whole.
int pyramidDepth(const VolumeSynthesisOptions& o) {
  int top = 0;
  while ((1 << top) < std::max({o.dims.x, o.dims.y, o.dims.z})) ++top;
  if (!o.periodic) return top;
  int depth = 0;
  while (depth < top && o.dims.x % (2 << depth) == 0 && o.dims.y % (2 << depth) == 0 &&
         o.dims.z % (2 << depth) == 0)
    ++depth;
  return depth;
}

// One axis of a level's window: `need` widened by `margin`. Without --periodic it stops at the
// faces; a periodic window runs past them (its voxels wrap) and, once it would cover the whole
// side, is the whole side and wraps itself.
void widen(int needLo, int needHi, int margin, int side, bool periodic, int& lo, int& hi, bool& wraps) {
  lo = needLo - margin, hi = needHi + margin, wraps = false;
  if (!periodic) {
    lo = std::max(lo, 0), hi = std::min(hi, side);
  } else if (hi - lo >= side) {
    lo = 0, hi = side, wraps = true;
  }
}

std::vector<LevelPlan> planLevels(const VolumeSynthesisOptions& o, const Box& region, int corrected) {
  const int top = pyramidDepth(o);
  std::vector<LevelPlan> plan(std::size_t(top) + 1);
  Box need = region;
  for (int l = top; l >= 0; --l) {
    LevelPlan& level = plan[std::size_t(l)];
    level.spacing = 1 << (top - l);
    level.periodic = o.periodic;
    level.dims = {ceilDiv(o.dims.x, level.spacing), ceilDiv(o.dims.y, level.spacing),
                  ceilDiv(o.dims.z, level.spacing)};
    const int finestFirst = top - l;
    level.appearance = finestFirst < corrected ? finestFirst : -1;
    const int margin = level.appearance >= 0 ? correctionMargin(o.corrections) : 0;
    Box& w = level.window;
    widen(need.lo.x, need.hi.x, margin, level.dims.x, o.periodic, w.lo.x, w.hi.x, level.wraps[0]);
    widen(need.lo.y, need.hi.y, margin, level.dims.y, o.periodic, w.lo.y, w.hi.y, level.wraps[1]);
    widen(need.lo.z, need.hi.z, margin, level.dims.z, o.periodic, w.lo.z, w.hi.z, level.wraps[2]);
    // floor and ceiling of half, also for a periodic window's negative coordinates
    need.lo = {w.lo.x >> 1, w.lo.y >> 1, w.lo.z >> 1};
    need.hi = {(w.hi.x + 1) >> 1, (w.hi.y + 1) >> 1, (w.hi.z + 1) >> 1};
  }
  return plan;
}

// The frame steering level voxel (x,y,z): the field at the centre of the finest voxels it covers.
Frame frameAt(const VolumeSynthesisOptions& o, const LevelPlan& level, int x, int y, int z) {
  if (!o.field) return Frame::Identity();
  const Voxel v = level.onLevel(x, y, z);
  x = v.x, y = v.y, z = v.z;
  const int half = level.spacing / 2;
  return o.field->at(std::min(x * level.spacing + half, o.dims.x - 1),
                     std::min(y * level.spacing + half, o.dims.y - 1),
                     std::min(z * level.spacing + half, o.dims.z - 1));
}

Coord wrapped(const ExemplarDomain& domain, Coord c) {
  for (int a = 0; a < 3; ++a) c[std::size_t(a)] = domain.wrap(a, c[std::size_t(a)]);
  return c;
}

Coord shifted(const ExemplarDomain& domain, const Coord& c, const Eigen::Vector3f& offset) {
  return wrapped(domain, {c[0] + int(std::lround(offset.x())), c[1] + int(std::lround(offset.y())),
                          c[2] + int(std::lround(offset.z()))});
}

// Eq. 2's hash H: a fixed function of the level and the voxel, in [-1, 1]^3.
Eigen::Vector3f hashJitter(std::uint64_t seed, int level, const LevelPlan& plan, int x, int y, int z) {
  const std::uint64_t h = deriveSeed(seed, std::uint64_t(level), std::uint64_t(plan.dims.index(x, y, z)));
  auto unit = [&](int part) {
    return float(double((h >> (21 * part)) & 0x1fffff) / double(0x1fffff) * 2 - 1);
  };
  return {unit(0), unit(1), unit(2)};
}

// The start of a periodic pyramid whose coarsest level has several voxels: each its own random
// domain voxel, as the coarser levels' jitter (wider than the exemplar there) would leave them.
Coord randomStart(const ExemplarDomain& domain, std::uint64_t seed, const LevelPlan& plan, const Voxel& v) {
  if (plan.dims.count() == 1) return {0, 0, 0};
  Rng rng(deriveSeed(seed, 0x5354415254, std::uint64_t(plan.dims.index(v))));  // "START"
  Coord c{};
  for (std::size_t a = 0; a < 3; ++a) c[a] = int(uniformIndex(rng, std::uint64_t(domain.size[a])));
  return c;
}

// Eq. 1 (and 5 under a field) followed by eq. 2: children take the parent's coordinate plus their
// offset at this level's spacing, then a jitter of up to r x spacing.
CoordinateGrid upsample(const CoordinateGrid* parent, const ExemplarDomain& domain,
                        const VolumeSynthesisOptions& o, const LevelPlan& level, int levelIndex) {
  CoordinateGrid grid{level.window.lo, level.window.dims(), level.wraps, {}};
  grid.coords.resize(grid.dims.count());
  const float h = float(level.spacing);
  tbb::parallel_for(level.window.lo.z, level.window.hi.z, [&](int z) {
    for (int y = level.window.lo.y; y < level.window.hi.y; ++y)
      for (int x = level.window.lo.x; x < level.window.hi.x; ++x) {
        const Voxel v = level.onLevel(x, y, z);
        Coord c = parent ? Coord{} : randomStart(domain, o.seed, level, v);
        Eigen::Vector3f offset = Eigen::Vector3f::Zero();
        if (parent) {
          // shifts and masks: floor and parity also for a periodic window's negative coordinates
          c = parent->at(x >> 1, y >> 1, z >> 1);
          const Eigen::Vector3f child(float(x & 1) - 0.5f, float(y & 1) - 0.5f, float(z & 1) - 0.5f);
          offset = h * (frameAt(o, level, x, y, z).transpose() * child) + Eigen::Vector3f::Constant(0.5f * h);
        }
        offset += float(o.jitter) * h * hashJitter(o.seed, levelIndex, level, v.x, v.y, v.z);
        grid.set(grid.index(x, y, z), shifted(domain, c, offset));
      }
  });
  return grid;
}

constexpr int kDiagonals = 8;
constexpr int kMaxK = 16;  // the largest similarity set size

Eigen::Vector3f diagonal(int d) { return {d & 1 ? 1.f : -1.f, d & 2 ? 1.f : -1.f, d & 4 ? 1.f : -1.f}; }

// The offsets a voxel reads for each diagonal (eq. 3-4, or 6-7 under a frame), in whole voxels:
// the output voxels it reads (the diagonal and the three sub-neighbours one step further along each
// of its axes), the exemplar offset that turns what each holds into a prediction for the diagonal,
// and the offset from a diagonal neighbour's similar voxels to candidates for the centre.
struct Reads {
  std::array<std::array<Voxel, 4>, kDiagonals> output;
  std::array<std::array<Voxel, 4>, kDiagonals> correction;
  std::array<Voxel, kDiagonals> toCentre;
};

Voxel rounded(const Eigen::Vector3f& v) {
  return {int(std::lround(v.x())), int(std::lround(v.y())), int(std::lround(v.z()))};
}

Eigen::Vector3f asVector(const Voxel& v) { return {float(v.x), float(v.y), float(v.z)}; }

Reads readsFor(const Frame& frame, float h) {
  Reads r;
  const Frame inverse = frame.transpose();
  for (std::size_t d = 0; d < kDiagonals; ++d) {
    const Eigen::Vector3f delta = diagonal(int(d));
    for (std::size_t t = 0; t < 4; ++t) {
      Eigen::Vector3f further = delta;
      if (t > 0) further[Eigen::Index(t - 1)] *= 2;
      r.output[d][t] = rounded(frame * further);
      // the exemplar coordinate at p + frame * delta, predicted from the one held at p + output
      r.correction[d][t] = rounded(h * (delta - inverse * asVector(r.output[d][t])));
    }
    r.toCentre[d] = rounded(-h * (inverse * asVector(r.output[d][0])));
  }
  return r;
}

// Wraps c into [0, size) when it is at most one period outside, as every offset here is.
int wrapNear(int c, int size) { return c < 0 ? c + size : c >= size ? c - size : c; }

struct Corrector {
  const ExemplarDomain& domain;
  const AppearanceLevel& appearance;
  const VolumeSynthesisOptions& o;
  const LevelPlan& level;
  Reads isometric = readsFor(Frame::Identity(), float(level.spacing));

  std::size_t featureIndex(const Coord& c, const Voxel& offset) const {
    return domain.index(wrapNear(c[0] + offset.x, domain.size[0]), wrapNear(c[1] + offset.y, domain.size[1]),
                        wrapNear(c[2] + offset.z, domain.size[2]));
  }

  // Sum of squared feature differences over the 8 diagonals of candidate u (exemplar-space, spacing
  // h), given up once it passes `bound`.
  float distance(const float* target, const Coord& u, float bound) const {
    const int D = appearance.dims, h = level.spacing;
    const std::array<int, 2> xs{wrapNear(u[0] - h, domain.size[0]), wrapNear(u[0] + h, domain.size[0])};
    const std::array<int, 2> ys{wrapNear(u[1] - h, domain.size[1]), wrapNear(u[1] + h, domain.size[1])};
    const std::array<int, 2> zs{wrapNear(u[2] - h, domain.size[2]), wrapNear(u[2] + h, domain.size[2])};
    float sum = 0;
    for (int d = 0; d < kDiagonals && sum < bound; ++d) {
      const float* f = appearance.feature(domain.index(xs[d & 1], ys[(d >> 1) & 1], zs[(d >> 2) & 1]));
      const float* t = target + d * D;
      for (int i = 0; i < D; ++i) sum += (t[i] - f[i]) * (t[i] - f[i]);
    }
    return sum;
  }

  Coord corrected(const CoordinateGrid& grid, int x, int y, int z, std::vector<float>& target) const {
    const int D = appearance.dims;
    const Frame frame = frameAt(o, level, x, y, z);
    const Frame inverse = frame.transpose();
    const float h = float(level.spacing);
    const Reads reads = o.field ? readsFor(frame, h) : isometric;
    std::fill(target.begin(), target.end(), 0.f);
    for (std::size_t d = 0; d < kDiagonals; ++d)
      for (std::size_t t = 0; t < 4; ++t) {
        const Voxel& at = reads.output[d][t];
        const float* f = appearance.feature(
            featureIndex(grid.extendedAt(x + at.x, y + at.y, z + at.z, inverse, h), reads.correction[d][t]));
        for (int i = 0; i < D; ++i) target[d * std::size_t(D) + std::size_t(i)] += 0.25f * f[i];
      }
    Coord best = grid.at(x, y, z);
    float bestDistance = distance(target.data(), best, std::numeric_limits<float>::infinity());
    const int k = o.k;
    // Where the output is coherent most neighbours propose the same voxel: each is measured once.
    std::array<std::size_t, kDiagonals * kMaxK + 1> tried;
    std::size_t triedCount = 0;
    tried[triedCount++] = domain.index(best[0], best[1], best[2]);
    for (std::size_t d = 0; d < kDiagonals; ++d) {
      const Voxel& at = reads.output[d][0];
      const std::int32_t* set =
          &appearance
               .similar[featureIndex(grid.extendedAt(x + at.x, y + at.y, z + at.z, inverse, h), {0, 0, 0}) *
                        std::size_t(k)];
      for (int m = 0; m < k; ++m) {
        const std::size_t member = featureIndex(coordOf(std::size_t(set[m])), reads.toCentre[d]);
        if (std::find(tried.begin(), tried.begin() + std::ptrdiff_t(triedCount), member) !=
            tried.begin() + std::ptrdiff_t(triedCount))
          continue;
        tried[triedCount++] = member;
        const Coord candidate = coordOf(member);
        const float dist = distance(target.data(), candidate, bestDistance);
        if (dist < bestDistance) {
          bestDistance = dist;
          best = candidate;
        }
      }
    }
    return best;
  }

  Coord coordOf(std::size_t i) const {
    const auto sx = std::size_t(domain.size[0]), sy = std::size_t(domain.size[1]);
    return {int(i % sx), int(i / sx % sy), int(i / (sx * sy))};
  }
};

// One pass: 8 subpasses, one per parity class of (x, y, z) mod 2; a subpass reads the grid as the
// earlier ones left it and writes its voxels only when all of them are done, so neither the order
// within it nor the thread count matters (under a frame a voxel may read others of its class).
void correctionPass(CoordinateGrid& grid, const Corrector& corrector) {
  const int D = corrector.appearance.dims;
  auto first = [](int lo, int parity) { return lo + ((lo & 1) != parity ? 1 : 0); };
  auto count = [](int first, int end) { return first < end ? (end - first + 1) / 2 : 0; };
  for (int parity = 0; parity < 8; ++parity) {
    const Voxel start{first(grid.lo.x, parity & 1), first(grid.lo.y, (parity >> 1) & 1),
                      first(grid.lo.z, (parity >> 2) & 1)};
    const Dims members{count(start.x, grid.lo.x + grid.dims.x), count(start.y, grid.lo.y + grid.dims.y),
                       count(start.z, grid.lo.z + grid.dims.z)};
    auto voxelOf = [&](int i, int j, int k) {
      return Voxel{start.x + 2 * i, start.y + 2 * j, start.z + 2 * k};
    };
    std::vector<Coord> updates(members.count());
    tbb::parallel_for(0, members.z, [&](int k) {
      std::vector<float> target(std::size_t(kDiagonals * D));
      for (int j = 0; j < members.y; ++j)
        for (int i = 0; i < members.x; ++i) {
          const Voxel v = voxelOf(i, j, k);
          updates[members.index(i, j, k)] = corrector.corrected(grid, v.x, v.y, v.z, target);
        }
    });
    for (int k = 0; k < members.z; ++k)
      for (int j = 0; j < members.y; ++j)
        for (int i = 0; i < members.x; ++i) {
          const Voxel v = voxelOf(i, j, k);
          grid.set(grid.index(v.x, v.y, v.z), updates[members.index(i, j, k)]);
        }
  }
}

void checkOptions(const DenseVolume& exemplar, const VolumeSynthesisOptions& o) {
  if (exemplar.channels != 1 && exemplar.channels != 3)
    throw InputError("the exemplar volume must have 1 (density) or 3 (colour) channels");
  if (exemplar.values.size() != exemplar.dims.count() * std::size_t(exemplar.channels))
    throw std::logic_error("synthesizeFromVolume: the exemplar's values do not match its dimensions");
  if (!std::all_of(exemplar.values.begin(), exemplar.values.end(), [](float v) { return std::isfinite(v); }))
    throw InputError("the exemplar volume holds values that are not finite (NaN or infinity)");
  for (const int side : {o.dims.x, o.dims.y, o.dims.z})
    if (side < 2 || side > 1024)
      throw OptionError("--size and --dims must be in [2, 1024], got " + std::to_string(side));
  auto number = [](double v) {
    std::ostringstream text;
    text << v;
    return text.str();
  };
  auto inRange = [&](const std::string& name, double v, double lo, double hi) {
    if (!(v >= lo && v <= hi))
      throw OptionError(name + " must be in [" + number(lo) + ", " + number(hi) + "], got " + number(v));
  };
  inRange("--jitter", o.jitter, 0, 2);
  inRange("--k", o.k, 1, kMaxK);
  inRange("--exclusion", o.exclusion, 1, 31);
  inRange("--pca-dims", o.pcaDims, 1, 64);
  inRange("--corrections", o.corrections, 0, 8);
  inRange("--levels", o.levels, 0, 11);
  if (o.window < 3 || o.window > 9 || o.window % 2 == 0)
    throw OptionError("--appearance must be odd and in [3, 9], got " + std::to_string(o.window));
  if (o.field && !(o.field->dims == o.dims))
    throw std::logic_error("synthesizeFromVolume: field dims differ from the output's");
  if (o.region) {
    const Box& r = *o.region;
    if (!(r.lo.x >= 0 && r.lo.y >= 0 && r.lo.z >= 0 && r.hi.x <= o.dims.x && r.hi.y <= o.dims.y &&
          r.hi.z <= o.dims.z && r.lo.x < r.hi.x && r.lo.y < r.hi.y && r.lo.z < r.hi.z))
      throw OptionError(
          "--region must be a non-empty box X0 Y0 Z0 X1 Y1 Z1 inside the output (0 <= X0 < X1 <= " +
          std::to_string(o.dims.x) + ", likewise for Y and Z)");
  }
}

// A periodic output is a torus at every corrected level only when each such level halves exactly
// into the next coarser one and has even sides (its 2x2x2 parity classes then wrap too).
void checkPeriodicSize(const VolumeSynthesisOptions& o, int corrected) {
  const int multiple = 1 << corrected;
  if (!o.periodic || (o.dims.x % multiple == 0 && o.dims.y % multiple == 0 && o.dims.z % multiple == 0))
    return;
  auto sizes = [&](bool up) {
    auto side = [&](int s) {
      return std::to_string(up ? ceilDiv(s, multiple) * multiple : std::max(s / multiple, 1) * multiple);
    };
    return side(o.dims.x) + "x" + side(o.dims.y) + "x" + side(o.dims.z);
  };
  const std::string down = sizes(false), up = sizes(true);
  throw OptionError("--periodic needs every output side to be a multiple of " + std::to_string(multiple) +
                    " (one halving per corrected level, " + std::to_string(corrected) +
                    " here; fewer --levels lower it), got " + std::to_string(o.dims.x) + "x" +
                    std::to_string(o.dims.y) + "x" + std::to_string(o.dims.z) + ": " + down +
                    (up == down ? "" : " or " + up) + " would tile");
}

// Levels whose window (window x spacing) fits in half the domain's smallest side.
int correctableLevels(const ExemplarDomain& domain, int window) {
  const int smallest = std::min({domain.size[0], domain.size[1], domain.size[2]});
  int levels = 0;
  while (2 * window * (1 << levels) <= smallest) ++levels;
  return std::max(levels, 1);
}

}  // namespace

VolumeAnalysisSize volumeAnalysisSize(const Dims& exemplar, const VolumeSynthesisOptions& o) {
  const int border = o.window / 2;
  const ExemplarDomain domain{{exemplar.x - 2 * border, exemplar.y - 2 * border, exemplar.z - 2 * border},
                              border};
  if (o.window < 1 || std::min({domain.size[0], domain.size[1], domain.size[2]}) < o.window) return {};
  const int allowed = correctableLevels(domain, o.window);
  return {double(domain.count()), o.levels > 0 ? std::min(o.levels, allowed) : allowed};
}

namespace {

void copyOut(const CoordinateGrid& grid, const ExemplarDomain& domain, const DenseVolume& exemplar,
             VolumeSynthesisResult& result) {
  const Box& box = result.box;
  const Dims dims = box.dims();
  result.values = {dims, exemplar.channels,
                   std::vector<float>(dims.count() * std::size_t(exemplar.channels))};
  result.source.resize(dims.count());
  tbb::parallel_for(0, dims.z, [&](int k) {
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        const Coord c = grid.at(box.lo.x + i, box.lo.y + j, box.lo.z + k);
        const Coord e{c[0] + domain.border, c[1] + domain.border, c[2] + domain.border};
        std::copy_n(exemplar.at(e[0], e[1], e[2]), exemplar.channels, result.values.at(i, j, k));
        result.source[dims.index(i, j, k)] = {float(e[0]), float(e[1]), float(e[2])};
      }
  });
}

}  // namespace

struct VolumeSynthesizer::Analysis {
  DenseVolume exemplar;
  VolumeSynthesisOptions options;
  ExemplarDomain domain;
  int corrected = 0;
  std::vector<AppearanceLevel> appearance;      // finest first
  std::vector<VolumeLevelStatistics> analysed;  // the analysis figures, finest first
  double seconds = 0;
};

VolumeSynthesizer::VolumeSynthesizer(const DenseVolume& exemplar, const VolumeSynthesisOptions& o)
    : analysis_(std::make_unique<Analysis>()) {
  const auto start = std::chrono::steady_clock::now();
  checkOptions(exemplar, o);
  const ThreadLimit threadLimit(o.threads);
  Analysis& a = *analysis_;
  a.exemplar = exemplar;
  a.options = o;
  a.options.region.reset();
  a.domain = synthesis::detail::exemplarDomain(exemplar.dims, o.window);
  const int allowed = correctableLevels(a.domain, o.window);
  if (o.levels > allowed)
    throw OptionError("--levels " + std::to_string(o.levels) + " is more than this exemplar allows (" +
                      std::to_string(allowed) + ": each level's " + std::to_string(o.window) +
                      "^3 window times its spacing must fit in half the exemplar)");
  a.corrected = o.levels > 0 ? o.levels : allowed;
  checkPeriodicSize(o, a.corrected);
  const synthesis::detail::AppearanceOptions appearanceOptions{o.window, o.pcaDims, o.k, o.exclusion};
  a.appearance.resize(std::size_t(a.corrected));
  a.analysed.resize(std::size_t(a.corrected));
  // Coarsest first, as the synthesis needs them; a large exemplar's analysis takes a while: say so.
  for (int level = a.corrected - 1; level >= 0; --level) {
    // Every level analyses the whole domain (at its spacing): they take about as long each.
    if (o.progress)
      o.progress("analysing the exemplar (" + std::to_string(a.corrected - level) + "/" +
                     std::to_string(a.corrected) + ")",
                 double(a.corrected - 1 - level) / a.corrected);
    const auto levelStart = std::chrono::steady_clock::now();
    AppearanceLevel& appearance = a.appearance[std::size_t(level)];
    appearance = synthesis::detail::buildAppearanceLevel(a.exemplar, a.domain, 1 << level, appearanceOptions);
    VolumeLevelStatistics& stats = a.analysed[std::size_t(level)];
    stats.appearanceDims = appearance.dims;
    stats.keptVariance = appearance.keptVariance;
    stats.similarityFallbackShare = appearance.excludedFallbackShare;
    stats.analysisSeconds = secondsSince(levelStart);
  }
  a.seconds = secondsSince(start);
}

VolumeSynthesizer::~VolumeSynthesizer() = default;
VolumeSynthesizer::VolumeSynthesizer(VolumeSynthesizer&&) noexcept = default;
VolumeSynthesizer& VolumeSynthesizer::operator=(VolumeSynthesizer&&) noexcept = default;

std::size_t VolumeSynthesizer::finestWindowVoxels(const Box& box) const {
  return planLevels(analysis_->options, box, analysis_->corrected).back().window.dims().count();
}

VolumeSynthesisResult VolumeSynthesizer::synthesize(const Box& box) const {
  const auto start = std::chrono::steady_clock::now();
  const Analysis& a = *analysis_;
  const VolumeSynthesisOptions& o = a.options;
  VolumeSynthesisOptions checked = o;
  checked.region = box;
  checkOptions(a.exemplar, checked);
  const ThreadLimit threadLimit(o.threads);

  VolumeSynthesisResult result;
  result.box = box;
  result.statistics.domain = a.domain.size;
  result.statistics.analysisSeconds = a.seconds;
  const std::vector<LevelPlan> plan = planLevels(o, box, a.corrected);
  // The share done counts correction passes by their voxels: upsampling and jitter are cheap beside
  // them, and the finest level's passes take most of the time.
  double passVoxelsDone = 0, passVoxels = 0;
  for (const LevelPlan& level : plan)
    if (level.appearance >= 0) passVoxels += double(level.window.dims().count()) * o.corrections;
  std::unique_ptr<CoordinateGrid> grid;
  for (std::size_t l = 0; l < plan.size(); ++l) {
    const LevelPlan& level = plan[l];
    VolumeLevelStatistics stats =
        level.appearance >= 0 ? a.analysed[std::size_t(level.appearance)] : VolumeLevelStatistics{};
    stats.spacing = level.spacing;
    stats.synthesised = level.window.dims();
    stats.corrected = level.appearance >= 0;
    const auto levelStart = std::chrono::steady_clock::now();
    auto next = std::make_unique<CoordinateGrid>(upsample(grid.get(), a.domain, o, level, int(l)));
    const std::string name = "level " + std::to_string(l + 1) + "/" + std::to_string(plan.size()) +
                             " (spacing " + std::to_string(level.spacing);
    const bool corrected = level.appearance >= 0 && o.corrections > 0;
    if (corrected) {
      const Corrector corrector{a.domain, a.appearance[std::size_t(level.appearance)], o, level};
      for (int pass = 0; pass < o.corrections; ++pass) {
        correctionPass(*next, corrector);
        passVoxelsDone += double(level.window.dims().count());
        if (o.progress)
          o.progress(
              name + ", correction " + std::to_string(pass + 1) + "/" + std::to_string(o.corrections) + ")",
              passVoxelsDone / passVoxels);
      }
    }
    if (o.progress && !corrected)
      o.progress(name + ")", passVoxels > 0 ? passVoxelsDone / passVoxels : double(l + 1) / plan.size());
    grid = std::move(next);
    stats.seconds = secondsSince(levelStart);
    result.statistics.levels.push_back(stats);
  }
  copyOut(*grid, a.domain, a.exemplar, result);
  result.statistics.seconds = a.seconds + secondsSince(start);
  return result;
}

VolumeSynthesisResult synthesizeFromVolume(const DenseVolume& exemplar, const VolumeSynthesisOptions& o) {
  const VolumeSynthesizer synthesizer(exemplar, o);
  return synthesizer.synthesize(o.region.value_or(Box::of(o.dims)));
}

}  // namespace solidtex
