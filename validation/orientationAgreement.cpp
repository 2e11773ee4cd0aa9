#include "validation/orientationAgreement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <Eigen/Eigenvalues>

#include "common/gaussianFilter.h"

namespace solidtex {
namespace {

/// Correlation weights for offsets -r..r: out(i) = sum_t w[t + r] in(clamp(i + t)).
using Kernel = std::vector<float>;

int radiusOf(double sigma) { return std::max(1, int(std::ceil(3 * sigma))); }

/// The Gaussian derivative, scaled so that a unit ramp has derivative 1 (sigma 0: central differences).
Kernel gaussianDerivative(double sigma) {
  if (sigma <= 0) return {-0.5f, 0.f, 0.5f};
  const int r = radiusOf(sigma);
  std::vector<double> w(std::size_t(2 * r + 1));
  double moment = 0;
  for (int t = -r; t <= r; ++t) {
    w[std::size_t(t + r)] = t * std::exp(-t * t / (2 * sigma * sigma));
    moment += t * w[std::size_t(t + r)];
  }
  Kernel k(w.size());
  for (std::size_t i = 0; i < w.size(); ++i) k[i] = float(w[i] / moment);
  return k;
}

/// out = in correlated with `kernel` along `axis` (0 x, 1 y, 2 z), clamp-to-edge.
void convolve(const std::vector<float>& in, std::vector<float>& out, const Dims& dims, int axis,
              const Kernel& kernel) {
  correlateAlong(in.data(), out.data(), dims, 1, axis, kernel);
}

template <typename Body>
void forEachSlice(const Dims& dims, Body body) {
  tbb::parallel_for(tbb::blocked_range<int>(0, dims.z), [&](const tbb::blocked_range<int>& ks) {
    for (int k = ks.begin(); k < ks.end(); ++k) body(k);
  });
}

}  // namespace

OrientationAgreement orientationAgreement(
    const DenseVolume& volume, const std::function<Eigen::Vector3f(int, int, int)>& expectedDirection,
    const OrientationOptions& options) {
  const Dims& dims = volume.dims;
  if (volume.channels < 1 || dims.x < 0 || dims.y < 0 || dims.z < 0 ||
      volume.values.size() != dims.count() * std::size_t(volume.channels))
    throw std::invalid_argument("orientationAgreement: the volume's values do not match its size");
  if (!(options.gradientSigma >= 0) || !(options.tensorSigma >= 0))
    throw std::invalid_argument("orientationAgreement: the sigmas must not be negative");
  OrientationAgreement result;
  const int margin = options.margin >= 0 ? options.margin
                                         : int(std::ceil(2 * (options.gradientSigma + options.tensorSigma)));
  if (dims.count() == 0 || dims.x <= 2 * margin || dims.y <= 2 * margin || dims.z <= 2 * margin)
    return result;

  const std::size_t n = dims.count(), slice = std::size_t(dims.x) * std::size_t(dims.y);
  const Kernel smooth = gaussianKernel(options.gradientSigma),
               derive = gaussianDerivative(options.gradientSigma);
  std::vector<float> f(n), t1(n), t2(n);
  std::array<std::vector<float>, 3> g{std::vector<float>(n), std::vector<float>(n), std::vector<float>(n)};
  // Structure tensor components xx, xy, xz, yy, yz, zz, summed over the channels.
  std::array<std::vector<float>, 6> tensor;
  for (auto& c : tensor) c.assign(n, 0.f);
  for (int c = 0; c < volume.channels; ++c) {
    forEachSlice(dims, [&](int k) {
      for (std::size_t v = std::size_t(k) * slice; v < std::size_t(k + 1) * slice; ++v)
        f[v] = volume.values[v * std::size_t(volume.channels) + std::size_t(c)];
    });
    convolve(f, t1, dims, 2, smooth);
    convolve(t1, t2, dims, 1, smooth);
    convolve(t2, g[0], dims, 0, derive);
    convolve(t1, t2, dims, 1, derive);
    convolve(t2, g[1], dims, 0, smooth);
    convolve(f, t1, dims, 2, derive);
    convolve(t1, t2, dims, 1, smooth);
    convolve(t2, g[2], dims, 0, smooth);
    forEachSlice(dims, [&](int k) {
      for (std::size_t v = std::size_t(k) * slice; v < std::size_t(k + 1) * slice; ++v) {
        const float x = g[0][v], y = g[1][v], z = g[2][v];
        tensor[0][v] += x * x;
        tensor[1][v] += x * y;
        tensor[2][v] += x * z;
        tensor[3][v] += y * y;
        tensor[4][v] += y * z;
        tensor[5][v] += z * z;
      }
    });
  }
  const Kernel window = gaussianKernel(options.tensorSigma);
  if (window.size() > 1)
    for (auto& component : tensor) {
      convolve(component, t1, dims, 0, window);
      convolve(t1, t2, dims, 1, window);
      convolve(t2, component, dims, 2, window);
    }

  // Voxels whose gradient energy is a rounding error (of the volume's mean energy, or of its values'
  // magnitude: float derivatives of a constant are not exactly zero) have no orientation.
  std::vector<double> traceSums(std::size_t(dims.z), 0.0);
  std::vector<float> maxAbs(std::size_t(dims.z), 0.f);
  forEachSlice(dims, [&](int k) {
    double sum = 0;
    float largest = 0;
    for (std::size_t v = std::size_t(k) * slice; v < std::size_t(k + 1) * slice; ++v) {
      sum += double(tensor[0][v]) + tensor[3][v] + tensor[5][v];
      for (int c = 0; c < volume.channels; ++c)
        largest =
            std::max(largest, std::abs(volume.values[v * std::size_t(volume.channels) + std::size_t(c)]));
    }
    traceSums[std::size_t(k)] = sum;
    maxAbs[std::size_t(k)] = largest;
  });
  double meanTrace = 0, valueScale = 0;
  for (int k = 0; k < dims.z; ++k) {
    meanTrace += traceSums[std::size_t(k)];
    valueScale = std::max(valueScale, double(maxAbs[std::size_t(k)]));
  }
  meanTrace /= double(n);
  const double flatTrace = std::max(1e-6 * meanTrace, std::pow(1e-5 * valueScale, 2) * volume.channels);

  std::vector<double> cosSums(std::size_t(dims.z), 0.0);
  std::vector<std::size_t> counted(std::size_t(dims.z), 0), totals(std::size_t(dims.z), 0);
  tbb::parallel_for(tbb::blocked_range<int>(margin, dims.z - margin), [&](const tbb::blocked_range<int>& ks) {
    for (int k = ks.begin(); k < ks.end(); ++k) {
      double cosSum = 0;
      std::size_t count = 0, total = 0;
      for (int j = margin; j < dims.y - margin; ++j)
        for (int i = margin; i < dims.x - margin; ++i) {
          const Eigen::Vector3d expected = expectedDirection(i, j, k).cast<double>();
          const double length = expected.norm();
          if (!(length > 0) || !std::isfinite(length)) continue;
          ++total;
          const std::size_t v = dims.index(i, j, k);
          Eigen::Matrix3d m;
          m << tensor[0][v], tensor[1][v], tensor[2][v],  //
              tensor[1][v], tensor[3][v], tensor[4][v],   //
              tensor[2][v], tensor[4][v], tensor[5][v];
          if (!(m.trace() > flatTrace)) continue;
          Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
          eigen.computeDirect(m);
          const double l1 = eigen.eigenvalues()(2), l2 = std::max(0.0, eigen.eigenvalues()(1));
          if (!(l1 > 0) || (l1 - l2) / (l1 + l2) < options.minCoherence) continue;
          ++count;
          cosSum += std::abs(eigen.eigenvectors().col(2).normalized().dot(expected / length));
        }
      cosSums[std::size_t(k)] = cosSum;
      counted[std::size_t(k)] = count;
      totals[std::size_t(k)] = total;
    }
  });
  double cosSum = 0;
  for (int k = 0; k < dims.z; ++k) {
    cosSum += cosSums[std::size_t(k)];
    result.voxelsCounted += counted[std::size_t(k)];
    result.voxelsTotal += totals[std::size_t(k)];
  }
  if (result.voxelsCounted > 0) result.meanAbsCos = cosSum / double(result.voxelsCounted);
  return result;
}

}  // namespace solidtex
