#include "validation/particleTruth.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "common/Random.h"
#include "common/srgb.h"
#include "particles/rotation.h"

namespace solidtex {
namespace {

constexpr int kTriesPerParticle = 4000;
constexpr std::size_t kMostParticles = 1'000'000;  // beyond this a truth takes minutes, not seconds
// Equal volume puts a polytope's vertices beyond the sphere's radius; drawing again past this reach
// keeps the longest particle, and so what fits the volume, predictable.
constexpr double kPolytopeReach = 1.3;
constexpr double kUnitSphereVolume = 4.0 / 3.0 * std::numbers::pi;

// One particle to place: the semi-axes of its equal-volume ellipsoid, whatever its shape.
struct Particle {
  int classIndex = 0;
  Eigen::Vector3d semiAxes;
  double volume() const { return kUnitSphereVolume * semiAxes.prod(); }
};

// The anisotropy's proportions at unit volume (all ones for an isotropic truth).
Eigen::Vector3d alignedProportions(const ParticleTruthOptions& options) {
  if (options.anisotropy.empty()) return Eigen::Vector3d::Ones();
  const Eigen::Vector3d a(options.anisotropy[0], options.anisotropy[1], options.anisotropy[2]);
  return a / std::cbrt(a.prod());
}

// Centred log stretches, then the smallest axis flattened against the other two: it times
// flatten^(2/3), they times flatten^(-1/3), so their ratio changes by flatten and the volume not.
Eigen::Vector3d axisStretches(const ParticleTruthOptions& options, Rng& rng) {
  Eigen::Vector3d logs;
  for (int a = 0; a < 3; ++a) logs[a] = (2 * uniform01(rng) - 1) * std::log(options.elongation);
  logs.array() -= logs.mean();
  Eigen::Index smallest = 0;
  logs.minCoeff(&smallest);
  const double logFlatten = std::log(options.flatten);
  logs.array() -= logFlatten / 3;
  logs[smallest] += logFlatten;
  return logs.array().exp() * alignedProportions(options).array();
}

// The sizes to place: drawn until their volumes fill the asked fraction, largest first.
std::vector<Particle> drawPopulation(const ParticleTruthOptions& options, Rng& rng) {
  double shareTotal = 0;
  for (const ParticleClass& c : options.classes) shareTotal += c.share;
  const double target = options.volumeFraction * double(options.dims.count());
  std::vector<Particle> population;
  for (double filled = 0; filled < target;) {
    if (population.size() == kMostParticles)
      throw InputError("the truth would hold over " + std::to_string(kMostParticles) +
                       " particles: raise the radii or lower the fraction or the dimensions");
    Particle p;
    double pick = uniform01(rng) * shareTotal;
    while (p.classIndex + 1 < int(options.classes.size()) &&
           pick >= options.classes[std::size_t(p.classIndex)].share)
      pick -= options.classes[std::size_t(p.classIndex++)].share;
    const ParticleClass& c = options.classes[std::size_t(p.classIndex)];
    // Two spreads at most: one freak size would dominate a small truth's volume distribution.
    const double radius =
        c.meanRadius * std::exp(c.radiusSpread * std::clamp(standardNormal(rng), -2.0, 2.0));
    p.semiAxes = radius * axisStretches(options, rng);
    filled += p.volume();
    population.push_back(p);
  }
  std::stable_sort(population.begin(), population.end(),
                   [](const Particle& a, const Particle& b) { return a.volume() > b.volume(); });
  return population;
}

// A particle's shape at unit semi-axes, scaled to the unit sphere's volume so that the semi-axes
// alone set every shape's volume.
struct UnitShape {
  double exponent = 2;  // ellipsoid and superellipsoid: sum |u_i / scale|^p <= 1
  double scale = 1;
  std::vector<Eigen::Vector4d> faces;  // polytope: (n, h) with n.u <= h; empty for the others
  double reach = 1;                    // the largest |u| inside

  bool contains(const Eigen::Vector3d& u) const {
    if (!faces.empty())
      return std::all_of(faces.begin(), faces.end(),
                         [&](const Eigen::Vector4d& f) { return f.head<3>().dot(u) <= f[3]; });
    const Eigen::Vector3d v = u.cwiseAbs() / scale;
    if (exponent == 2) return v.squaredNorm() <= 1;
    return v.array().pow(exponent).sum() <= 1;
  }
};

UnitShape superellipsoid(double p) {
  const double volume = 8 * std::pow(std::tgamma(1 + 1 / p), 3) / std::tgamma(1 + 3 / p);
  UnitShape shape;
  shape.exponent = p;
  shape.scale = std::cbrt(kUnitSphereVolume / volume);
  // |u|_2 <= 3^(1/2 - 1/p) |u|_p: the corners along the diagonals reach furthest.
  shape.reach = shape.scale * std::max(1.0, std::pow(3.0, 0.5 - 1 / p));
  return shape;
}

// The convex hull's faces by brute force over vertex triples: with a dozen vertices in general
// position that is cheaper and simpler than a hull algorithm. Appends faces, returns the volume.
double hullFaces(const std::vector<Eigen::Vector3d>& vertices, std::vector<Eigen::Vector4d>& faces) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : vertices) centre += v / double(vertices.size());
  double volume = 0;
  const std::size_t n = vertices.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        const Eigen::Vector3d cross = (vertices[j] - vertices[i]).cross(vertices[k] - vertices[i]);
        const Eigen::Vector3d normal = cross.normalized();
        const double offset = normal.dot(vertices[i]);
        bool below = true, above = true;
        for (const Eigen::Vector3d& v : vertices) {
          below = below && normal.dot(v) - offset <= 1e-9;
          above = above && normal.dot(v) - offset >= -1e-9;
        }
        if (below == above) continue;  // vertices on both sides: not a face
        const double sign = below ? 1 : -1;
        faces.emplace_back(sign * normal.x(), sign * normal.y(), sign * normal.z(), sign * offset);
        volume += cross.norm() / 2 * std::abs(offset - normal.dot(centre)) / 3;
      }
  return volume;
}

// Vertices spread evenly over the sphere (a Fibonacci spiral), each moved at random: random
// polytopes whose vertices stay near the equal-volume sphere, unlike the slivers uniform points make.
UnitShape polytope(Rng& rng) {
  for (;;) {
    const int count = 12 + int(uniformIndex(rng, 5));
    std::vector<Eigen::Vector3d> vertices;
    for (int i = 0; i < count; ++i) {
      const double z = 1 - (2 * i + 1) / double(count), ring = std::sqrt(1 - z * z);
      const double angle = i * std::numbers::pi * (3 - std::sqrt(5.0));
      const Eigen::Vector3d jitter(standardNormal(rng), standardNormal(rng), standardNormal(rng));
      vertices.push_back(
          (Eigen::Vector3d(ring * std::cos(angle), ring * std::sin(angle), z) + 0.25 * jitter).normalized());
    }
    UnitShape shape;
    shape.scale = std::cbrt(kUnitSphereVolume / hullFaces(vertices, shape.faces));
    if (shape.scale > kPolytopeReach) continue;
    for (Eigen::Vector4d& f : shape.faces) f[3] *= shape.scale;
    shape.reach = shape.scale;
    return shape;
  }
}

UnitShape unitShapeOf(const ParticleTruthOptions& options, Rng& rng) {
  switch (options.shape) {
    case TruthShape::Superellipsoid:
      return superellipsoid(options.exponent);
    case TruthShape::Polytope:
      return polytope(rng);
    case TruthShape::Ellipsoid:
      break;
  }
  return {};
}

// The furthest any shape of the options reaches, in semi-axes.
double largestReach(const ParticleTruthOptions& options) {
  switch (options.shape) {
    case TruthShape::Superellipsoid:
      return superellipsoid(options.exponent).reach;
    case TruthShape::Polytope:
      return kPolytopeReach;
    case TruthShape::Ellipsoid:
      break;
  }
  return 1;
}

struct Footprint {
  std::vector<Voxel> inside;  // offsets from the centre voxel
  std::vector<Voxel> near;    // inside and their 26 neighbours: must all be free
};

// The voxels of a randomly rotated particle centred at a random point of a voxel, and the ring that
// keeps others from touching it. Centred on voxel centres, every particle would be digitized
// symmetrically, and its sections would look more regular than any solid's or photo's.
Footprint footprintOf(const Particle& p, const ParticleTruthOptions& options, Rng& rng) {
  const Eigen::Matrix3d r = options.anisotropy.empty() ? randomRotation(rng) : Eigen::Matrix3d::Identity();
  const UnitShape shape = unitShapeOf(options, rng);
  const Eigen::Matrix3d toUnit = p.semiAxes.cwiseInverse().asDiagonal() * r.transpose();
  const Eigen::Vector3d offset(uniform01(rng) - 0.5, uniform01(rng) - 0.5, uniform01(rng) - 0.5);
  const int half = int(std::ceil(shape.reach * p.semiAxes.maxCoeff())) + 1;
  const Dims box{2 * half + 1, 2 * half + 1, 2 * half + 1};
  std::vector<std::uint8_t> grown(box.count(), 0);
  Footprint f;
  for (int k = -half; k <= half; ++k)
    for (int j = -half; j <= half; ++j)
      for (int i = -half; i <= half; ++i)
        if (shape.contains(toUnit * (Eigen::Vector3d(i, j, k) - offset))) f.inside.push_back({i, j, k});
  if (f.inside.empty()) f.inside.push_back({0, 0, 0});  // a tiny particle between voxel centres
  for (const Voxel& v : f.inside)
    for (int dk = -1; dk <= 1; ++dk)
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const std::size_t idx = box.index(v.x + half + di, v.y + half + dj, v.z + half + dk);
          if (grown[idx]) continue;
          grown[idx] = 1;
          f.near.push_back({v.x + di, v.y + dj, v.z + dk});
        }
  return f;
}

int wrap(int v, int n) { return ((v % n) + n) % n; }

std::size_t wrappedIndex(const Dims& dims, const Voxel& centre, const Voxel& offset) {
  return dims.index(wrap(centre.x + offset.x, dims.x), wrap(centre.y + offset.y, dims.y),
                    wrap(centre.z + offset.z, dims.z));
}

bool isFree(const std::vector<std::int32_t>& ids, const Dims& dims, const Voxel& centre, const Footprint& f) {
  return std::none_of(f.near.begin(), f.near.end(),
                      [&](const Voxel& o) { return ids[wrappedIndex(dims, centre, o)] != 0; });
}

// The middle section across `plane` (the axis it holds fixed: 2 for xy, 1 for xz, 0 for yz), its
// first free axis across and the second down.
cv::Mat renderSection(const ParticleTruth& truth, const ParticleTruthOptions& options, int plane, Rng& rng) {
  const Dims& dims = truth.volume.dims;
  std::vector<float> shade(truth.classOf.size());
  for (float& s : shade) s = float(1 + 0.12 * (uniform01(rng) - 0.5));
  const int edges[3] = {dims.x, dims.y, dims.z};
  const int across = plane == 0 ? 1 : 0, down = plane == 2 ? 1 : 2;
  cv::Mat photo(edges[down], edges[across], CV_32FC3);
  for (int j = 0; j < photo.rows; ++j)
    for (int i = 0; i < photo.cols; ++i) {
      int at[3];
      at[plane] = edges[plane] / 2;
      at[across] = i;
      at[down] = j;
      const std::int32_t id = truth.volume.particleId[dims.index(at[0], at[1], at[2])];
      if (id == 0) {
        photo.at<cv::Vec3f>(j, i) = options.backgroundSrgb;
        continue;
      }
      const ParticleClass& c = options.classes[std::size_t(truth.classOf[std::size_t(id - 1)])];
      const double speckle = c.grain > 0 ? 1 + c.grain * standardNormal(rng) : 1;
      photo.at<cv::Vec3f>(j, i) = c.srgb * float(shade[std::size_t(id - 1)] * std::max(0.0, speckle));
    }
  // A lens blurs what it sees and the sensor then adds its noise, so the noise stays sharp.
  if (options.blur > 0) cv::GaussianBlur(photo, photo, cv::Size(), options.blur, options.blur);
  for (int j = 0; j < photo.rows; ++j)
    for (int i = 0; i < photo.cols; ++i) {
      cv::Vec3f& c = photo.at<cv::Vec3f>(j, i);
      for (int ch = 0; ch < 3; ++ch)
        c[ch] = std::clamp(float(c[ch] + options.noise * standardNormal(rng)), 0.f, 1.f);
    }
  return photo;
}

void validateClass(const ParticleClass& c, const ParticleTruthOptions& options) {
  if (!(c.meanRadius >= 1))
    throw OptionError("--small-radius, --medium-radius and --large-radius must be at least 1 voxel");
  if (!(c.share > 0 && c.share <= 1)) throw OptionError("--large-share must be between 0 and 1");
  if (!(c.radiusSpread >= 0 && c.radiusSpread <= 1)) throw OptionError("--spread must be between 0 and 1");
  if (!(c.grain >= 0 && c.grain <= 1)) throw OptionError("--medium-grain must be between 0 and 1");
  // Radii stop at two spreads; centred log stretches reach elongation^(4/3), flattening widens the
  // other axes by flatten^(-1/3). A periodic volume must hold the longest particle with room to
  // spare, or it would touch its own image.
  // Turned at random, any axis may lie along the shortest edge; aligned, each axis has its own.
  const double longest = 2 * c.meanRadius * std::exp(2 * c.radiusSpread) *
                         std::pow(options.elongation, 4.0 / 3.0) / std::cbrt(options.flatten) *
                         largestReach(options);
  const Eigen::Vector3d along = alignedProportions(options) * longest;
  const int edges[3] = {options.dims.x, options.dims.y, options.dims.z};
  for (int a = 0; a < 3; ++a) {
    const double across = options.anisotropy.empty() ? longest : along[a];
    const int edge = options.anisotropy.empty() ? std::min({edges[0], edges[1], edges[2]}) : edges[a];
    if (across + 4 > edge)
      throw OptionError("the largest " + std::string(truthShapeName(options.shape)) + "s (" +
                        std::to_string(int(std::ceil(across))) + " voxels across) do not fit " +
                        (options.anisotropy.empty() ? "the smallest of --dims ("
                                                    : "--dims along " + std::string(1, "xyz"[a]) + " (") +
                        std::to_string(edge) +
                        "): lower --small-radius, --large-radius, --spread or --elongation, or raise --dims");
  }
}

// Each limit names the command line's option, as the library's users see the same words in its docs.
void checkRange(const char* option, double value, double low, double high, bool openLow = false,
                bool openHigh = false) {
  if ((openLow ? value > low : value >= low) && (openHigh ? value < high : value <= high)) return;
  std::ostringstream text;
  text << option << " must be " << (openLow ? "above " : "at least ") << low << " and "
       << (openHigh ? "below " : "at most ") << high << " (got " << value << ")";
  throw OptionError(text.str());
}

void validate(const ParticleTruthOptions& options) {
  const Dims& d = options.dims;
  if (d.x < 16 || d.y < 16 || d.z < 16 || d.count() > (std::size_t(1) << 30))
    throw OptionError("--dims must be at least 16 on each edge and at most 2^30 voxels in all (got " +
                      std::to_string(d.x) + " " + std::to_string(d.y) + " " + std::to_string(d.z) + ")");
  checkRange("--noise", options.noise, 0, 1);
  checkRange("--blur", options.blur, 0, 16);
  checkRange("--fraction", options.volumeFraction, 0, 0.5, true, true);
  if (options.classes.empty()) throw OptionError("truth needs at least one class of particles");
  checkRange("--elongation", options.elongation, 1, 3);
  // Thinner than 1:5 and a small particle is a voxel or two thick: its shape is lost.
  checkRange("--flatten", options.flatten, 0.2, 1);
  // Below 1 the shape is no longer convex; far above 16 it is a box with voxel-sharp edges.
  checkRange("--exponent", options.exponent, 1, 16);
  if (!options.anisotropy.empty()) {
    if (options.anisotropy.size() != 3) throw OptionError("--anisotropy takes three proportions: x y z");
    for (double a : options.anisotropy) checkRange("--anisotropy", a, 0, 1e3, true);
    const auto [least, most] = std::minmax_element(options.anisotropy.begin(), options.anisotropy.end());
    // Beyond 1:10 a small particle is a voxel or two thick along its shortest axis.
    if (*most > 10 * *least)
      throw OptionError("--anisotropy: the largest proportion may be at most 10 times the smallest");
  }
  for (const ParticleClass& c : options.classes) validateClass(c, options);
}

}  // namespace

TruthShape parseTruthShape(const std::string& name) {
  if (name == "ellipsoid") return TruthShape::Ellipsoid;
  if (name == "superellipsoid") return TruthShape::Superellipsoid;
  if (name == "polytope") return TruthShape::Polytope;
  throw OptionError("unknown truth shape '" + name + "': use ellipsoid, superellipsoid or polytope");
}

const char* truthShapeName(TruthShape shape) {
  switch (shape) {
    case TruthShape::Superellipsoid:
      return "superellipsoid";
    case TruthShape::Polytope:
      return "polytope";
    case TruthShape::Ellipsoid:
      break;
  }
  return "ellipsoid";
}

ParticleTruth makeParticleTruth(const ParticleTruthOptions& options) {
  validate(options);
  Rng rng(options.seed);
  const Dims& dims = options.dims;
  ParticleTruth truth;
  truth.volume.dims = dims;
  const std::vector<Particle> population = drawPopulation(options, rng);  // may refuse: before the grid
  truth.volume.particleId.assign(dims.count(), 0);
  std::size_t occupied = 0;
  for (const Particle& p : population) {
    const Footprint f = footprintOf(p, options, rng);
    for (int t = 0; t < kTriesPerParticle; ++t) {
      const Voxel centre{int(uniformIndex(rng, std::uint64_t(dims.x))),
                         int(uniformIndex(rng, std::uint64_t(dims.y))),
                         int(uniformIndex(rng, std::uint64_t(dims.z)))};
      if (!isFree(truth.volume.particleId, dims, centre, f)) continue;
      truth.classOf.push_back(p.classIndex);
      truth.volumes.push_back(double(f.inside.size()));
      for (const Voxel& o : f.inside)
        truth.volume.particleId[wrappedIndex(dims, centre, o)] = std::int32_t(truth.classOf.size());
      occupied += f.inside.size();
      break;
    }
  }
  truth.volumeFraction = double(occupied) / double(dims.count());

  std::vector<Rgb> linear(options.classes.size() + 1);
  const auto toLinear = [](const cv::Vec3f& s) {
    return Rgb{srgbToLinear(s[0]), srgbToLinear(s[1]), srgbToLinear(s[2])};
  };
  linear[0] = toLinear(options.backgroundSrgb);
  for (std::size_t c = 0; c < options.classes.size(); ++c) linear[c + 1] = toLinear(options.classes[c].srgb);
  truth.volume.color.resize(dims.count());
  for (std::size_t v = 0; v < dims.count(); ++v) {
    const std::int32_t id = truth.volume.particleId[v];
    truth.volume.color[v] = linear[id > 0 ? std::size_t(truth.classOf[std::size_t(id - 1)]) + 1 : 0];
  }
  truth.volume.metadata["voxels_per_pixel"] = "1";
  truth.volume.metadata["volume_fraction"] = std::to_string(truth.volumeFraction);
  truth.photo = renderSection(truth, options, 2, rng);
  truth.photoXz = renderSection(truth, options, 1, rng);
  truth.photoYz = renderSection(truth, options, 0, rng);
  return truth;
}

}  // namespace solidtex
