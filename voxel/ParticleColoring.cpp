#include "voxel/ParticleColoring.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <tbb/parallel_for.h>
#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "common/Random.h"
#include "common/randomDirection.h"
#include "segmentation/particleShading.h"

namespace solidtex {
namespace {

Rgb clamp01(const cv::Vec3f& c) {
  return {std::clamp(c[0], 0.f, 1.f), std::clamp(c[1], 0.f, 1.f), std::clamp(c[2], 0.f, 1.f)};
}

/// A parallel projection onto a plane, scaled from voxels to photo pixels.
struct Projection {
  Eigen::Vector3d u, v;
};

Projection randomProjection(Rng& rng, double pixelsPerVoxel) {
  const Eigen::Vector3d d = randomDirection(rng);
  const Eigen::Vector3d helper = std::abs(d.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u = d.cross(helper).normalized();
  return {u * pixelsPerVoxel, d.cross(u) * pixelsPerVoxel};
}

/// `image` with the pixels under `holes` replaced by Gaussian-weighted means of the pixels around
/// them (normalized convolution at doubling widths, each hole pixel from the narrowest that reaches
/// it): smooth, within the range of the known pixels, and a few blurs' work even for a large photo.
cv::Mat fillFromAround(const cv::Mat& image, const cv::Mat& holes) {
  cv::Mat known;
  cv::bitwise_not(holes, known);
  known.convertTo(known, CV_32F, 1.0 / 255);
  cv::Mat known3, weighted;
  cv::merge(std::vector<cv::Mat>(3, known), known3);
  cv::multiply(image, known3, weighted);
  cv::Mat filled = image.clone(), done = known > 0.5f;
  const double widest = 4.0 * std::max(image.rows, image.cols);
  for (double sigma = 1; cv::countNonZero(done) < int(done.total()) && sigma < widest; sigma *= 2) {
    cv::Mat numerator, denominator;
    // A Gaussian much wider than the image along an axis weighs the reflected image almost
    // evenly, so capping each axis' sigma at twice that side changes little; uncapped, OpenCV's
    // vertical pass holds about 8 sigma rows of the image's width (a 20000x8 strip: gigabytes).
    const double sx = std::min(sigma, 2.0 * image.cols), sy = std::min(sigma, 2.0 * image.rows);
    cv::GaussianBlur(weighted, numerator, {0, 0}, sx, sy, cv::BORDER_REFLECT);
    cv::GaussianBlur(known, denominator, {0, 0}, sx, sy, cv::BORDER_REFLECT);
    for (int r = 0; r < image.rows; ++r)
      for (int c = 0; c < image.cols; ++c) {
        const float w = denominator.at<float>(r, c);
        if (done.at<std::uint8_t>(r, c) || w < (sigma * 2 >= widest ? 1e-30f : 1e-3f)) continue;
        filled.at<cv::Vec3f>(r, c) = numerator.at<cv::Vec3f>(r, c) / w;
        done.at<std::uint8_t>(r, c) = 255;
      }
  }
  return filled;
}

/// The background residual with the particles (and their shadow rims) filled in from around them,
/// so the tiled background carries no ghost outlines of the photo's particles. The rim is as wide as
/// still leaves a third of the background to fill from: a crowded photo has little to spare.
cv::Mat fillParticleHoles(const ExemplarStats& stats) {
  const int backgroundPixels = cv::countNonZero(stats.backgroundMask);
  if (backgroundPixels == 0) return cv::Mat::zeros(stats.backgroundResidual.size(), CV_32FC3);
  cv::Mat holes, particles;
  cv::bitwise_not(stats.backgroundMask, particles);
  for (const int rim : {11, 7, 5, 3, 1}) {
    cv::dilate(particles, holes, cv::getStructuringElement(cv::MORPH_ELLIPSE, {rim, rim}));
    if (3 * (int(holes.total()) - cv::countNonZero(holes)) >= backgroundPixels) break;
  }
  return fillFromAround(stats.backgroundResidual, holes);
}

int wrap(double x, int n) {
  const int i = int(std::floor(x)) % n;
  return i < 0 ? i + n : i;
}

// The background residual laid into 3D. A projection cannot map a torus onto the photo, so in a
// periodic volume each voxel within kFadeBand voxels of a face mixes the residual at its position
// with the residual at its image across that face, half and half at the face itself: both sides of
// the face then read the same mix. Mixing independent grain lowers its contrast, so the mix of the
// residual less its mean is divided by the root of the summed squared weights (variance-preserving
// blending). The mean, alike at every lookup, is added back as is: divided too, it would brighten
// or darken the faces, most of all the corners, where eight lookups mix.
class BackgroundResidual {
public:
  BackgroundResidual(const cv::Mat& residual, const Projection& projection, Dims dims, bool periodic)
      : residual_(residual), projection_(projection), dims_(dims), periodic_(periodic) {
    if (!periodic) return;
    const cv::Scalar mean = cv::mean(residual);
    mean_ = cv::Vec3f(float(mean[0]), float(mean[1]), float(mean[2]));
    centred_ = residual - mean;
  }

  cv::Vec3f at(int x, int y, int z) const {
    if (!periodic_) return lookup(residual_, Eigen::Vector3d(x, y, z));
    std::array<Fade, 3> fades{fadeOf(x, dims_.x), fadeOf(y, dims_.y), fadeOf(z, dims_.z)};
    cv::Vec3f sum(0, 0, 0);
    double squares = 0;
    for (int corner = 0; corner < 8; ++corner) {
      double weight = 1;
      Eigen::Vector3d p(x, y, z);
      for (int a = 0; a < 3; ++a) {
        const bool across = (corner >> a) & 1;
        if (across && fades[std::size_t(a)].shift == 0) weight = 0;
        weight *= across ? 1 - fades[std::size_t(a)].own : fades[std::size_t(a)].own;
        if (across) p[a] += fades[std::size_t(a)].shift;
      }
      if (weight <= 0) continue;
      sum += lookup(centred_, p) * float(weight);
      squares += weight * weight;
    }
    return mean_ + sum / float(std::sqrt(squares));
  }

private:
  static constexpr double kFadeBand = 16;

  // The weight of a voxel's own position, and the shift to its image across the nearer face.
  struct Fade {
    double own = 1;
    int shift = 0;
  };

  static Fade fadeOf(int i, int n) {
    const double band = std::max(1.0, std::min(kFadeBand, n / 4.0));
    const double below = i + 0.5, above = n - 0.5 - i;  // distances to the two faces
    if (below < band) return {0.5 + 0.5 * below / band, n};
    if (above < band) return {0.5 + 0.5 * above / band, -n};
    return {};
  }

  cv::Vec3f lookup(const cv::Mat& image, const Eigen::Vector3d& p) const {
    return image.at<cv::Vec3f>(wrap(p.dot(projection_.v), image.rows),
                               wrap(p.dot(projection_.u), image.cols));
  }

  const cv::Mat& residual_;
  cv::Vec3f mean_;   ///< periodic: the residual's mean
  cv::Mat centred_;  ///< periodic: the residual less its mean
  Projection projection_;
  Dims dims_;
  bool periodic_;
};

// The offset from c to p, in a periodic volume the shortest one around the torus.
Eigen::Vector3d offsetFrom(const std::array<double, 3>& c, const Eigen::Vector3d& p, Dims dims,
                           bool periodic) {
  Eigen::Vector3d d = p - Eigen::Vector3d(c[0], c[1], c[2]);
  if (!periodic) return d;
  const double n[3] = {double(dims.x), double(dims.y), double(dims.z)};
  for (int a = 0; a < 3; ++a) d[a] -= n[a] * std::round(d[a] / n[a]);
  return d;
}

// The particles' insides from a grain block: each photo particle's residual split into its shading,
// which is projected as the residual was (smooth, it draws no stripes), and its grain, replaced by
// the block's deviation from its mean laid at an offset of each particle's own (so no two show the
// same piece) and scaled by the ratio of the source's grain spread to the block's.
class ParticleGrain {
public:
  ParticleGrain(const TiledMatrix& block, const ExemplarStats& stats,
                const std::vector<ParticlePaint>& particles, Rng& rng)
      : block_(block) {
    double sum[3] = {0, 0, 0}, squares = 0;
    for (const Rgb& c : block.color)
      for (int k = 0; k < 3; ++k) sum[k] += c[std::size_t(k)];
    const double n = double(block.color.size());
    for (int k = 0; k < 3; ++k) mean_[std::size_t(k)] = float(sum[k] / n);
    for (const Rgb& c : block.color)
      for (int k = 0; k < 3; ++k) squares += std::pow(c[std::size_t(k)] - mean_[std::size_t(k)], 2);
    const double blockSpread = std::sqrt(squares / (3 * n));
    std::vector<float> sourceContrast;
    for (const Particle2D& source : stats.particles) {
      ResidualScales scales = splitResidual(source);
      const double spread =
          std::sqrt(cv::norm(scales.grain, cv::NORM_L2SQR) / (3 * std::max(1.0, source.area)));
      sourceContrast.push_back(blockSpread > 0 ? float(spread / blockSpread) : 0.f);
      shading_.push_back(std::move(scales.shading));
    }
    for (const ParticlePaint& particle : particles) {
      contrast_.push_back(sourceContrast[std::size_t(particle.source)]);
      offsets_.push_back({int(uniformIndex(rng, std::uint64_t(block.dims.x))),
                          int(uniformIndex(rng, std::uint64_t(block.dims.y))),
                          int(uniformIndex(rng, std::uint64_t(block.dims.z)))});
    }
  }

  /// The residual to project for a photo particle: its shading.
  const cv::Mat& shading(int source) const { return shading_[std::size_t(source)]; }

  cv::Vec3f at(std::size_t particle, int x, int y, int z) const {
    const std::array<int, 3>& o = offsets_[particle];
    const Rgb& c = block_.color[block_.dims.index((x + o[0]) % block_.dims.x, (y + o[1]) % block_.dims.y,
                                                  (z + o[2]) % block_.dims.z)];
    const float k = contrast_[particle];
    return {k * (c[0] - mean_[0]), k * (c[1] - mean_[1]), k * (c[2] - mean_[2])};
  }

private:
  const TiledMatrix& block_;
  Rgb mean_{};
  std::vector<cv::Mat> shading_;
  std::vector<float> contrast_;
  std::vector<std::array<int, 3>> offsets_;
};

}  // namespace

struct ParticleColoring::State {
  ExemplarStats stats;
  Dims dims;
  std::vector<ParticlePaint> particles;
  bool periodic;
  std::optional<TiledMatrix> matrix, grain;
  std::vector<Projection> projections;
  std::optional<ParticleGrain> particleGrain;
  cv::Mat filled;
  std::optional<BackgroundResidual> backgroundResidual;
};

ParticleColoring::ParticleColoring(const ExemplarStats& stats, Dims dims,
                                   std::vector<ParticlePaint> particles, double voxelsPerPixel,
                                   std::uint64_t seed, bool periodic, std::optional<TiledMatrix> matrix,
                                   std::optional<TiledMatrix> grain) {
  auto state = std::make_unique<State>(State{
      stats, dims, std::move(particles), periodic, std::move(matrix), std::move(grain), {}, {}, {}, {}});
  Rng rng(deriveSeed(seed, 0xC0102));
  const Projection background = randomProjection(rng, 1.0 / voxelsPerPixel);
  state->projections.reserve(state->particles.size());
  for (const ParticlePaint& particle : state->particles)
    state->projections.push_back(randomProjection(rng, 1.0 / particle.voxelsPerPixel));
  if (state->grain) state->particleGrain.emplace(*state->grain, state->stats, state->particles, rng);
  if (!state->matrix) state->filled = fillParticleHoles(state->stats);
  state->backgroundResidual.emplace(state->filled, background, dims, periodic && !state->matrix);
  state_ = std::move(state);
}

ParticleColoring::~ParticleColoring() = default;

Rgb ParticleColoring::at(int x, int y, int z, std::int32_t id) const {
  const State& s = *state_;
  if (id == 0) {
    const TiledMatrix* matrix = s.matrix ? &*s.matrix : nullptr;
    return matrix
               ? matrix->color[matrix->dims.index(x % matrix->dims.x, y % matrix->dims.y, z % matrix->dims.z)]
               : clamp01(s.stats.backgroundColor + s.backgroundResidual->at(x, y, z));
  }
  const ParticlePaint& particle = s.particles[std::size_t(id - 1)];
  const Particle2D& source = s.stats.particles[std::size_t(particle.source)];
  const cv::Mat& residual = s.particleGrain ? s.particleGrain->shading(particle.source) : source.residual;
  const Projection& proj = s.projections[std::size_t(id - 1)];
  // Project about the particle's centre onto the centre of its photo particle's box.
  const Eigen::Vector3d local = offsetFrom(particle.centre, Eigen::Vector3d(x, y, z), s.dims, s.periodic);
  const int c = std::clamp(int(residual.cols * 0.5 + local.dot(proj.u)), 0, residual.cols - 1);
  const int r = std::clamp(int(residual.rows * 0.5 + local.dot(proj.v)), 0, residual.rows - 1);
  // Outside the photo particle's mask the residual is 0: the voxel keeps the mean colour.
  cv::Vec3f colour = source.color + residual.at<cv::Vec3f>(r, c);
  if (s.particleGrain) colour += s.particleGrain->at(std::size_t(id - 1), x, y, z);
  return clamp01(colour);
}

}  // namespace solidtex
