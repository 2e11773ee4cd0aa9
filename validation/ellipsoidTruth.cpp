#include "validation/ellipsoidTruth.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/Error.h"
#include "common/Random.h"
#include "particles/rotation.h"
#include "segmentation/analyzeExemplar.h"

namespace solidtex {
namespace {

constexpr int kTriesPerParticle = 4000;

double gaussian(Rng& rng) {
  const double u = 1 - uniform01(rng), v = uniform01(rng);  // u in (0,1]: log(u) is finite
  return std::sqrt(-2 * std::log(u)) * std::cos(2 * std::numbers::pi * v);
}

struct Ellipsoid {
  int classIndex = 0;
  Eigen::Vector3d semiAxes;
  double volume() const { return 4.0 / 3.0 * std::numbers::pi * semiAxes.prod(); }
};

// The sizes to place: drawn until their volumes fill the asked fraction, largest first.
std::vector<Ellipsoid> drawPopulation(const EllipsoidTruthOptions& options, Rng& rng) {
  double shareTotal = 0;
  for (const EllipsoidClass& c : options.classes) shareTotal += c.share;
  const double target = options.volumeFraction * double(options.dims.count());
  const double logElongation = std::log(options.elongation);
  std::vector<Ellipsoid> population;
  for (double filled = 0; filled < target;) {
    Ellipsoid e;
    double pick = uniform01(rng) * shareTotal;
    while (e.classIndex + 1 < int(options.classes.size()) && pick >= options.classes[std::size_t(e.classIndex)].share)
      pick -= options.classes[std::size_t(e.classIndex++)].share;
    const EllipsoidClass& c = options.classes[std::size_t(e.classIndex)];
    // Two spreads at most: one freak size would dominate a small truth's volume distribution.
    const double radius = c.meanRadius * std::exp(c.radiusSpread * std::clamp(gaussian(rng), -2.0, 2.0));
    Eigen::Vector3d logs;
    for (int a = 0; a < 3; ++a) logs[a] = (2 * uniform01(rng) - 1) * logElongation;
    logs.array() -= logs.mean();
    e.semiAxes = radius * logs.array().exp();
    filled += e.volume();
    population.push_back(e);
  }
  std::stable_sort(population.begin(), population.end(),
                   [](const Ellipsoid& a, const Ellipsoid& b) { return a.volume() > b.volume(); });
  return population;
}

struct Footprint {
  std::vector<Voxel> inside;  // offsets from the centre voxel
  std::vector<Voxel> near;    // inside and their 26 neighbours: must all be free
};

// The voxels of a randomly rotated ellipsoid centred in a voxel, and the ring that keeps others
// from touching it.
Footprint footprintOf(const Ellipsoid& e, Rng& rng) {
  const Eigen::Matrix3d r = randomRotation(rng);
  const Eigen::Matrix3d q = r * e.semiAxes.cwiseInverse().cwiseAbs2().asDiagonal() * r.transpose();
  Eigen::Vector3i half;
  for (int a = 0; a < 3; ++a) half[a] = int(std::ceil((r.row(a).transpose().cwiseProduct(e.semiAxes)).norm())) + 1;
  const Dims box{2 * half.x() + 1, 2 * half.y() + 1, 2 * half.z() + 1};
  std::vector<std::uint8_t> grown(box.count(), 0);
  Footprint f;
  for (int k = 0; k < box.z; ++k)
    for (int j = 0; j < box.y; ++j)
      for (int i = 0; i < box.x; ++i) {
        const Eigen::Vector3d d(i - half.x(), j - half.y(), k - half.z());
        if (d.dot(q * d) <= 1) f.inside.push_back({i - half.x(), j - half.y(), k - half.z()});
      }
  if (f.inside.empty()) f.inside.push_back({0, 0, 0});  // a tiny ellipsoid between voxel centres
  for (const Voxel& v : f.inside)
    for (int dk = -1; dk <= 1; ++dk)
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const std::size_t idx = box.index(v.x + half.x() + di, v.y + half.y() + dj, v.z + half.z() + dk);
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
  return std::none_of(f.near.begin(), f.near.end(), [&](const Voxel& o) { return ids[wrappedIndex(dims, centre, o)] != 0; });
}

cv::Mat renderSection(const EllipsoidTruth& truth, const EllipsoidTruthOptions& options, Rng& rng) {
  const Dims& dims = truth.volume.dims;
  std::vector<float> shade(truth.classOf.size());
  for (float& s : shade) s = float(1 + 0.12 * (uniform01(rng) - 0.5));
  cv::Mat photo(dims.y, dims.x, CV_32FC3);
  const int z = dims.z / 2;
  for (int j = 0; j < dims.y; ++j)
    for (int i = 0; i < dims.x; ++i) {
      const std::int32_t id = truth.volume.particleId[dims.index(i, j, z)];
      cv::Vec3f c = options.backgroundSrgb;
      if (id > 0) c = options.classes[std::size_t(truth.classOf[std::size_t(id - 1)])].srgb * shade[std::size_t(id - 1)];
      for (int ch = 0; ch < 3; ++ch) c[ch] = std::clamp(float(c[ch] + options.noise * gaussian(rng)), 0.f, 1.f);
      photo.at<cv::Vec3f>(j, i) = c;
    }
  return photo;
}

void validate(const EllipsoidTruthOptions& options) {
  const Dims& d = options.dims;
  if (d.x < 16 || d.y < 16 || d.z < 16 || d.count() > (std::size_t(1) << 30))
    throw InputError("truth dimensions must be at least 16 and at most 2^30 voxels in all");
  if (!(options.noise >= 0 && options.noise <= 1)) throw InputError("truth photo noise must be in [0, 1]");
  if (!(options.volumeFraction > 0 && options.volumeFraction < 0.5))
    throw InputError("truth volume fraction must be in (0, 0.5)");
  if (options.classes.empty()) throw InputError("truth needs at least one class of ellipsoids");
  if (!(options.elongation >= 1)) throw InputError("truth elongation must be at least 1");
  for (const EllipsoidClass& c : options.classes) {
    if (!(c.meanRadius >= 1 && c.share > 0 && c.radiusSpread >= 0))
      throw InputError("each ellipsoid class needs a radius of at least 1 voxel, a share above 0 and a spread of at least 0");
    // Radii stop at two spreads; centred log stretches reach elongation^(4/3). A periodic volume
    // must hold the longest axis with room to spare, or a particle would touch its own image.
    const double longest = 2 * c.meanRadius * std::exp(2 * c.radiusSpread) * std::pow(options.elongation, 4.0 / 3.0);
    if (longest + 4 > std::min({d.x, d.y, d.z}))
      throw InputError("the largest ellipsoids (" + std::to_string(int(std::ceil(longest))) +
                       " voxels long) do not fit the truth's smallest edge (" + std::to_string(std::min({d.x, d.y, d.z})) + ")");
  }
}

} // namespace

EllipsoidTruth makeEllipsoidTruth(const EllipsoidTruthOptions& options) {
  validate(options);
  Rng rng(options.seed);
  const Dims& dims = options.dims;
  EllipsoidTruth truth;
  truth.volume.dims = dims;
  truth.volume.particleId.assign(dims.count(), 0);
  std::size_t occupied = 0;
  for (const Ellipsoid& e : drawPopulation(options, rng)) {
    const Footprint f = footprintOf(e, rng);
    for (int t = 0; t < kTriesPerParticle; ++t) {
      const Voxel centre{int(uniformIndex(rng, std::uint64_t(dims.x))), int(uniformIndex(rng, std::uint64_t(dims.y))),
                         int(uniformIndex(rng, std::uint64_t(dims.z)))};
      if (!isFree(truth.volume.particleId, dims, centre, f)) continue;
      truth.classOf.push_back(e.classIndex);
      truth.volumes.push_back(double(f.inside.size()));
      for (const Voxel& o : f.inside) truth.volume.particleId[wrappedIndex(dims, centre, o)] = std::int32_t(truth.classOf.size());
      occupied += f.inside.size();
      break;
    }
  }
  truth.volumeFraction = double(occupied) / double(dims.count());

  std::vector<Rgb> linear(options.classes.size() + 1);
  const auto toLinear = [](const cv::Vec3f& s) { return Rgb{srgbToLinear(s[0]), srgbToLinear(s[1]), srgbToLinear(s[2])}; };
  linear[0] = toLinear(options.backgroundSrgb);
  for (std::size_t c = 0; c < options.classes.size(); ++c) linear[c + 1] = toLinear(options.classes[c].srgb);
  truth.volume.color.resize(dims.count());
  for (std::size_t v = 0; v < dims.count(); ++v) {
    const std::int32_t id = truth.volume.particleId[v];
    truth.volume.color[v] = linear[id > 0 ? std::size_t(truth.classOf[std::size_t(id - 1)]) + 1 : 0];
  }
  truth.volume.metadata["voxels_per_pixel"] = "1";
  truth.volume.metadata["volume_fraction"] = std::to_string(truth.volumeFraction);
  truth.photo = renderSection(truth, options, rng);
  return truth;
}

} // namespace solidtex
