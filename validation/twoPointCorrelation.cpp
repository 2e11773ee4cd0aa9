#include "validation/twoPointCorrelation.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <mutex>

#include <fftw3.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "common/Error.h"

namespace solidtex {
namespace {

// FFTW's planner is not thread-safe; executing a plan is.
std::mutex& plannerMutex() {
  static std::mutex m;
  return m;
}

struct FftwDeleter {
  void operator()(void* p) const { fftw_free(p); }
};

// The smallest size >= n whose prime factors are 2, 3, 5 and 7: the sizes FFTW is fast at.
int fastFftSize(int n) {
  for (int m = n;; ++m) {
    int r = m;
    for (int p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

std::array<int, 3> extentOf(const Dims& d) { return {d.x, d.y, d.z}; }

using RealBuffer = std::unique_ptr<double, FftwDeleter>;

// sum_x f(x) f(x + d) for every d of the (padded) torus: the inverse FFT of |F|^2.
RealBuffer cyclicAutocorrelation(const PhaseField& phase, const std::array<int, 3>& size) {
  const std::size_t nx = std::size_t(size[0]), ny = std::size_t(size[1]), nz = std::size_t(size[2]);
  const std::size_t real = nx * ny * nz, spectral = (nx / 2 + 1) * ny * nz;
  RealBuffer f(fftw_alloc_real(real));
  std::unique_ptr<fftw_complex, FftwDeleter> spectrum(fftw_alloc_complex(spectral));
  if (!f || !spectrum) throw std::bad_alloc();
  fftw_plan forward, backward;
  {
    std::lock_guard lock(plannerMutex());
    forward = fftw_plan_dft_r2c_3d(int(nz), int(ny), int(nx), f.get(), spectrum.get(), FFTW_ESTIMATE);
    backward = fftw_plan_dft_c2r_3d(int(nz), int(ny), int(nx), spectrum.get(), f.get(), FFTW_ESTIMATE);
  }
  std::fill(f.get(), f.get() + real, 0.0);
  const Dims& d = phase.dims;
  for (int k = 0; k < d.z; ++k)
    for (int j = 0; j < d.y; ++j)
      for (int i = 0; i < d.x; ++i)
        f.get()[(std::size_t(k) * ny + std::size_t(j)) * nx + std::size_t(i)] =
            phase.inside[d.index(i, j, k)];
  fftw_execute(forward);
  for (std::size_t i = 0; i < spectral; ++i) {
    const double re = spectrum.get()[i][0], im = spectrum.get()[i][1];
    spectrum.get()[i][0] = (re * re + im * im) / double(real);
    spectrum.get()[i][1] = 0;
  }
  fftw_execute(backward);
  {
    std::lock_guard lock(plannerMutex());
    fftw_destroy_plan(forward);
    fftw_destroy_plan(backward);
  }
  return f;
}

double excessLength(const std::vector<double>& curve, double limit) {
  if (curve.empty()) return 0;
  const double target = (curve[0] - limit) / std::exp(1.0);
  for (std::size_t r = 1; r < curve.size(); ++r) {
    const double a = curve[r - 1] - limit, b = curve[r] - limit;
    if (b <= target) return double(r - 1) + (a > b ? (a - target) / (a - b) : 0.0);
  }
  return double(curve.size());
}

// The radial curve, or where there is none the mean of the axis curves.
std::vector<double> isotropicCurve(const CorrelationCurves& c) {
  return c.radial.empty() ? meanOverAxes(c.axes) : c.radial;
}

}  // namespace

int correlationMaxDistance(const Dims& dims, int maxDistance) {
  int shortest = std::max(dims.x, dims.y);
  for (int n : extentOf(dims))
    if (n > 1) shortest = std::min(shortest, n);
  const int largest = std::max(1, shortest - 1);
  return maxDistance > 0 ? std::min(maxDistance, largest) : std::max(1, shortest / 4);
}

CorrelationCurves twoPointCorrelation(const PhaseField& phase, const TwoPointOptions& options) {
  if (phase.dims.count() == 0 || phase.inside.size() != phase.dims.count())
    throw InputError("two-point correlation of an empty field");
  const int R = correlationMaxDistance(phase.dims, options.maxDistance);
  const std::array<int, 3> n = extentOf(phase.dims);
  std::array<int, 3> size{}, reach{};
  for (int a = 0; a < 3; ++a) {
    reach[a] = n[a] > 1 ? R : 0;
    size[a] = options.periodic || n[a] == 1 ? n[a] : fastFftSize(n[a] + R);
  }
  const RealBuffer sums = cyclicAutocorrelation(phase, size);
  const auto valueAt = [&](int dx, int dy, int dz) {
    const std::array<int, 3> dv{dx, dy, dz};
    std::size_t index = 0;
    double pairs = 1;
    for (int a = 2; a >= 0; --a) {
      const int wrapped = (dv[a] % size[a] + size[a]) % size[a];
      index = index * std::size_t(size[a]) + std::size_t(wrapped);
      pairs *= options.periodic ? n[a] : n[a] - std::abs(dv[a]);
    }
    return sums.get()[index] / pairs;
  };
  CorrelationCurves out;
  out.phaseFraction = phase.fraction();
  for (int a = 0; a < 3; ++a) {
    if (n[a] == 1) continue;
    for (int r = 0; r <= R; ++r)
      out.axes[std::size_t(a)].push_back(valueAt(a == 0 ? r : 0, a == 1 ? r : 0, a == 2 ? r : 0));
  }
  std::vector<double> sum(std::size_t(R) + 1, 0.0), count(std::size_t(R) + 1, 0.0);
  for (int dz = -reach[2]; dz <= reach[2]; ++dz)
    for (int dy = -reach[1]; dy <= reach[1]; ++dy)
      for (int dx = -reach[0]; dx <= reach[0]; ++dx) {
        const long bin = std::lround(std::sqrt(double(dx * dx + dy * dy + dz * dz)));
        if (bin > R) continue;
        sum[std::size_t(bin)] += valueAt(dx, dy, dz);
        count[std::size_t(bin)] += 1;
      }
  for (std::size_t r = 0; r < sum.size(); ++r) out.radial.push_back(sum[r] / count[r]);
  out.correlationLength = excessLength(out.radial, out.phaseFraction * out.phaseFraction);
  return out;
}

CorrelationCurves twoPointClusterFunction(const Dims& dims, const std::vector<std::int32_t>& labels,
                                          int maxDistance) {
  if (dims.count() == 0 || labels.size() != dims.count())
    throw InputError("two-point cluster function of an empty field");
  const int R = correlationMaxDistance(dims, maxDistance);
  const std::array<int, 3> n = extentOf(dims);
  const std::array<std::size_t, 3> stride{1, std::size_t(dims.x), std::size_t(dims.x) * std::size_t(dims.y)};
  CorrelationCurves out;
  std::size_t occupied = 0;
  for (std::int32_t l : labels) occupied += l > 0;
  out.phaseFraction = double(occupied) / double(labels.size());
  for (int a = 0; a < 3; ++a) {
    if (n[a] == 1) continue;
    using Counts = std::vector<std::size_t>;
    const Counts same = tbb::parallel_reduce(
        tbb::blocked_range<int>(0, dims.z), Counts(std::size_t(R) + 1, 0),
        [&](const tbb::blocked_range<int>& zs, Counts acc) {
          for (int k = zs.begin(); k != zs.end(); ++k)
            for (int j = 0; j < dims.y; ++j)
              for (int i = 0; i < dims.x; ++i) {
                const std::array<int, 3> at{i, j, k};
                const std::size_t base = dims.index(i, j, k);
                const std::int32_t l = labels[base];
                if (l <= 0) continue;
                const int last = std::min(R, n[a] - 1 - at[a]);
                for (int r = 0; r <= last; ++r)
                  acc[std::size_t(r)] += labels[base + std::size_t(r) * stride[a]] == l;
              }
          return acc;
        },
        [](Counts x, const Counts& y) {
          for (std::size_t r = 0; r < x.size(); ++r) x[r] += y[r];
          return x;
        });
    const double across = double(dims.count()) / n[a];
    for (int r = 0; r <= R; ++r)
      out.axes[std::size_t(a)].push_back(double(same[std::size_t(r)]) / (across * (n[a] - r)));
  }
  out.correlationLength = excessLength(isotropicCurve(out), 0.0);
  return out;
}

std::vector<double> meanOverAxes(const std::array<std::vector<double>, 3>& axes) {
  std::vector<double> mean;
  int count = 0;
  for (const auto& a : axes) {
    if (a.empty()) continue;
    mean.resize(a.size(), 0.0);
    for (std::size_t r = 0; r < a.size(); ++r) mean[r] += a[r];
    ++count;
  }
  for (double& v : mean) v /= std::max(count, 1);
  return mean;
}

double curveDistance(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  if (n == 0) return 0;
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum / double(n));
}

}  // namespace solidtex
