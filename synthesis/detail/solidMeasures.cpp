#include "synthesis/detail/solidMeasures.h"

#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "common/Random.h"
#include "common/srgb.h"
#include "synthesis/detail/ExemplarNeighborhoods.h"
#include "synthesis/detail/SliceNeighborhoods.h"

namespace solidtex::synthesis {

namespace {

/// Periodic trilinear sample of the volume at continuous voxel coordinates.
void sampleTrilinear(const WorkVolume& v, const Eigen::Vector3d& p, float* out) {
  int i0[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double fl = std::floor(p[a]);
    i0[a] = int(fl);
    f[a] = p[a] - fl;
  }
  double acc[3] = {0, 0, 0};
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const double w = (dz ? f[2] : 1 - f[2]) * (dy ? f[1] : 1 - f[1]) * (dx ? f[0] : 1 - f[0]);
        const float* c = v.at(v.index(v.wrap(i0[0] + dx), v.wrap(i0[1] + dy), v.wrap(i0[2] + dz)));
        for (int k = 0; k < 3; ++k) acc[k] += w * c[k];
      }
  for (int k = 0; k < 3; ++k) out[k] = float(acc[k]);
}

double gaussian(Rng& rng) {
  const double u1 = std::max(uniform01(rng), 1e-300), u2 = uniform01(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.14159265358979323846 * u2);
}

/// Per column of `queries`, the squared distance to the nearest column of `exemplar`, per component.
std::vector<double> nearestSquaredDistances(const Eigen::MatrixXf& queries, const Eigen::MatrixXf& exemplar) {
  const Eigen::VectorXf exemplarNorms = exemplar.colwise().squaredNorm().transpose();
  const Eigen::Index Q = queries.cols();
  constexpr Eigen::Index chunk = 128;
  const Eigen::Index chunks = (Q + chunk - 1) / chunk;
  std::vector<double> best(std::size_t(Q), 0.0);
  tbb::parallel_for(Eigen::Index(0), chunks, [&](Eigen::Index c) {
    const Eigen::Index b = c * chunk, e = std::min(Q, b + chunk);
    const Eigen::MatrixXf q = queries.middleCols(b, e - b);
    const Eigen::MatrixXf dots = exemplar.transpose() * q;  // M x chunk
    for (Eigen::Index j = 0; j < e - b; ++j) {
      Eigen::Index nearest = 0;
      (exemplarNorms - 2.0f * dots.col(j)).minCoeff(&nearest);
      // Found by the expansion, measured directly: the expansion's cancellation error, raised to
      // the power gamma / 2, would swamp exact copies.
      const double d = (exemplar.col(nearest) - q.col(j)).cast<double>().squaredNorm();
      best[std::size_t(b + j)] = d / double(queries.rows());
    }
  });
  return best;
}

/// Mean of d^(gamma / 2) over the squared distances d.
double meanPower(const std::vector<double>& squared, double gamma) {
  double sum = 0;
  for (double d : squared) sum += std::pow(d, gamma / 2);
  return squared.empty() ? 0.0 : sum / double(squared.size());
}

}  // namespace

SliceEnergy sliceEnergy(const WorkVolume& v, const RgbImage& exemplar, const SliceMeasureOptions& options) {
  NeighborhoodShape shape{std::min({options.neighborhood, exemplar.width, exemplar.height})};
  const Eigen::MatrixXf ex = gatherExemplarNeighborhoods(exemplar, shape);
  const int D = shape.dims();
  Rng rng(options.seed);

  Eigen::MatrixXf axisQ(D, options.axisSamples);
  for (int s = 0; s < options.axisSamples; ++s) {
    const int axis = s % 3;
    std::array<int, 3> c{int(uniformIndex(rng, v.n)), int(uniformIndex(rng, v.n)),
                         int(uniformIndex(rng, v.n))};
    gatherSliceNeighborhood(v, axis, c, shape, axisQ.col(s).data());
  }

  Eigen::MatrixXf obliqueQ(D, options.obliqueSamples);
  for (int s = 0; s < options.obliqueSamples; ++s) {
    Eigen::Quaterniond q(gaussian(rng), gaussian(rng), gaussian(rng), gaussian(rng));
    q.normalize();
    const Eigen::Matrix3d R = q.toRotationMatrix();
    const Eigen::Vector3d origin(uniform01(rng) * v.n, uniform01(rng) * v.n, uniform01(rng) * v.n);
    float* out = obliqueQ.col(s).data();
    for (int j = shape.lo(); j <= shape.hi(); ++j)
      for (int i = shape.lo(); i <= shape.hi(); ++i, out += 3)
        sampleTrilinear(v, origin + double(i) * R.col(0) + double(j) * R.col(1), out);
  }

  const std::vector<double> axis = nearestSquaredDistances(axisQ, ex),
                            oblique = nearestSquaredDistances(obliqueQ, ex);
  return {meanPower(axis, kEnergyExponent), meanPower(oblique, kEnergyExponent), meanPower(axis, 2),
          meanPower(oblique, 2)};
}

double colorHistogramDistance(const float* rgb, std::size_t count, const RgbImage& exemplar, int bins) {
  const std::size_t cells = std::size_t(bins) * bins * bins;
  auto binOf = [&](const float* c) {
    std::size_t idx = 0;
    for (int k = 0; k < 3; ++k)
      idx = idx * bins + std::size_t(std::clamp(int(c[k] * float(bins)), 0, bins - 1));
    return idx;
  };
  std::vector<double> a(cells, 0.0), b(cells, 0.0);
  for (std::size_t i = 0; i < count; ++i) a[binOf(rgb + 3 * i)] += 1.0;
  const std::size_t pixels = std::size_t(exemplar.pixelCount());
  for (std::size_t i = 0; i < pixels; ++i) b[binOf(exemplar.data.data() + 3 * i)] += 1.0;
  double tv = 0;
  for (std::size_t i = 0; i < cells; ++i)
    tv += std::abs(a[i] / double(std::max<std::size_t>(count, 1)) -
                   b[i] / double(std::max<std::size_t>(pixels, 1)));
  return 0.5 * tv;
}

PositionHistogramStats positionHistogramStats(const std::vector<std::int32_t>& sources, int pixels) {
  PositionHistogramStats s;
  if (pixels <= 0) return s;
  std::vector<std::int64_t> h(pixels, 0);
  std::int64_t total = 0;
  for (std::int32_t p : sources)
    if (p >= 0 && p < pixels) {
      ++h[p];
      ++total;
    }
  if (total == 0) return s;
  std::int64_t used = 0;
  double entropy = 0, sq = 0;
  const double mean = double(total) / pixels;
  for (std::int64_t c : h) {
    if (c > 0) {
      ++used;
      const double p = double(c) / double(total);
      entropy -= p * std::log(p);
    }
    sq += (double(c) - mean) * (double(c) - mean);
  }
  s.coverage = double(used) / pixels;
  s.flatness = pixels > 1 ? entropy / std::log(double(pixels)) : 1.0;
  s.variation = std::sqrt(sq / pixels) / mean;
  return s;
}

WorkVolume srgbVolumeOf(const SolidVolume& volume, int exemplarWidth) {
  WorkVolume v;
  v.n = volume.dims.x;
  v.rgb.resize(v.count() * 3);
  for (std::size_t i = 0; i < v.count(); ++i)
    for (int c = 0; c < 3; ++c) v.rgb[3 * i + c] = linearToSrgb(volume.color[i][c]);
  if (!volume.sourcePosition.empty()) {
    v.source.resize(v.count());
    for (std::size_t i = 0; i < v.count(); ++i)
      v.source[i] = std::int32_t(std::lround(volume.sourcePosition[i][1])) * exemplarWidth +
                    std::int32_t(std::lround(volume.sourcePosition[i][0]));
  }
  return v;
}

}  // namespace solidtex::synthesis
