#include "placement/sectionSizing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include <Eigen/Dense>

#include "common/Error.h"
#include "common/randomDirection.h"

namespace solidtex {
namespace {

constexpr std::uint64_t kKernelStream = 0x6b65726e;  // "kern"
constexpr double kKernelSide = 32;  // voxels of the largest particle box the kernel is measured on

std::vector<Eigen::Vector3d> centresOf(const VoxelShape& shape) {
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < shape.dims.z; ++k)
    for (int j = 0; j < shape.dims.y; ++j)
      for (int i = 0; i < shape.dims.x; ++i)
        if (shape.inside[shape.dims.index(i, j, k)]) out.emplace_back(i, j, k);
  return out;
}

// A random plane cutting the shape: its section area is the count of voxel centres within half a
// voxel of it (a unit-thick slab holds area x 1 of volume), and the shape's extent along the normal
// is how likely a plane of a random family is to cut it at all.
void addSections(const std::vector<Eigen::Vector3d>& centres, int planes, double pixelsPerVoxel2,
                 const ExemplarStats& stats, Rng& rng, double perSample, Eigen::Ref<Eigen::Matrix<double, 10, 1>> column) {
  std::vector<double> along(centres.size());
  for (int p = 0; p < planes; ++p) {
    const Eigen::Vector3d n = randomDirection(rng);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < centres.size(); ++i) {
      along[i] = n.dot(centres[i]);
      lo = std::min(lo, along[i]);
      hi = std::max(hi, along[i]);
    }
    const double width = hi - lo + 1;
    const double at = lo - 0.5 + uniform01(rng) * width;
    const auto inSlab = std::count_if(along.begin(), along.end(), [&](double t) { return std::abs(t - at) < 0.5; });
    const double area = double(inSlab) * pixelsPerVoxel2;
    if (inSlab == 0 || area < stats.minArea) continue;
    column[stats.histogram.binOf(area)] += width * perSample;
  }
}

} // namespace

Sizing parseSizing(const std::string& name) {
  if (name == "bbox") return Sizing::Bbox;
  if (name == "sections") return Sizing::Sections;
  throw InputError("unknown sizing '" + name + "': use bbox or sections");
}

const char* sizingName(Sizing sizing) { return sizing == Sizing::Bbox ? "bbox" : "sections"; }

Eigen::Matrix<double, 10, 10> measureSectionKernel(const ExemplarStats& stats, const ParticleFactory& factory,
                                                   double voxelsPerPixel, double sizeFactor, std::uint64_t seed,
                                                   int shapesPerBin, int planesPerShape) {
  std::array<std::vector<SizePair>, 10> pairs;
  for (const Particle2D& p : stats.particles)
    if (!p.border && p.box.width > 0 && p.box.height > 0)
      pairs[std::size_t(stats.histogram.binOf(p.area))].push_back({p.box.width, p.box.height, 1});
  Eigen::Matrix<double, 10, 10> kernel = Eigen::Matrix<double, 10, 10>::Zero();
  Rng rng(deriveSeed(seed, kKernelStream));
  const auto scaled = [&](int pixels) { return std::max(1, int(std::lround(pixels * voxelsPerPixel * sizeFactor))); };
  const double pixelsPerVoxel2 = 1 / (voxelsPerPixel * voxelsPerPixel);
  for (int j = 0; j < 10; ++j) {
    const auto& bin = pairs[std::size_t(j)];
    if (bin.empty()) continue;
    for (int s = 0; s < shapesPerBin; ++s) {
      const SizePair& pair = bin[uniformIndex(rng, bin.size())];
      const ParticleSize size = factory.pickDepth(pair.width, pair.height, rng);
      const VoxelShape shape = factory.make(scaled(size.width), scaled(size.height), scaled(size.depth), rng);
      // Widths are in voxels: in photo pixels, as the plane spacing of the photo's own section.
      addSections(centresOf(shape), planesPerShape, pixelsPerVoxel2, stats, rng,
                  1.0 / (voxelsPerPixel * shapesPerBin * planesPerShape), kernel.col(j));
    }
  }
  return kernel;
}

Eigen::VectorXd nonNegativeLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  const Eigen::Index n = a.cols();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<bool> passive(std::size_t(n), false);
  const double tolerance = 1e-12 * std::max(1.0, a.norm() * b.norm());
  for (int outer = 0; outer < 3 * n; ++outer) {
    const Eigen::VectorXd gradient = a.transpose() * (b - a * x);
    Eigen::Index best = -1;
    for (Eigen::Index i = 0; i < n; ++i)
      if (!passive[std::size_t(i)] && gradient[i] > tolerance && (best < 0 || gradient[i] > gradient[best])) best = i;
    if (best < 0) break;
    passive[std::size_t(best)] = true;
    for (int inner = 0; inner < 3 * n; ++inner) {
      std::vector<Eigen::Index> set;
      for (Eigen::Index i = 0; i < n; ++i)
        if (passive[std::size_t(i)]) set.push_back(i);
      Eigen::MatrixXd sub(a.rows(), Eigen::Index(set.size()));
      for (std::size_t k = 0; k < set.size(); ++k) sub.col(Eigen::Index(k)) = a.col(set[k]);
      const Eigen::VectorXd z = sub.colPivHouseholderQr().solve(b);
      if (z.minCoeff() > 0) {
        x.setZero();
        for (std::size_t k = 0; k < set.size(); ++k) x[set[k]] = z[Eigen::Index(k)];
        break;
      }
      // Step from x towards z until the first passive coefficient reaches 0, and drop it.
      double alpha = 1;
      for (std::size_t k = 0; k < set.size(); ++k)
        if (z[Eigen::Index(k)] <= 0) alpha = std::min(alpha, x[set[k]] / (x[set[k]] - z[Eigen::Index(k)]));
      for (std::size_t k = 0; k < set.size(); ++k) x[set[k]] += alpha * (z[Eigen::Index(k)] - x[set[k]]);
      for (std::size_t k = 0; k < set.size(); ++k)
        if (x[set[k]] <= tolerance) {
          x[set[k]] = 0;
          passive[std::size_t(set[k])] = false;
        }
    }
  }
  return x;
}

namespace {

struct Unfolded {
  std::array<double, 10> ratios{};
  double residual = INFINITY;
};

Unfolded unfold(const Eigen::Matrix<double, 10, 10>& kernel, const std::array<double, 10>& photoRatios) {
  // Only bins the photo has particles of can be made; their columns are all the kernel has.
  std::vector<Eigen::Index> made;
  for (Eigen::Index j = 0; j < 10; ++j)
    if (photoRatios[std::size_t(j)] > 0 && kernel.col(j).sum() > 0) made.push_back(j);
  Unfolded out;
  if (made.empty()) return out;
  Eigen::MatrixXd a(10, Eigen::Index(made.size()));
  for (std::size_t k = 0; k < made.size(); ++k) a.col(Eigen::Index(k)) = kernel.col(made[k]);
  const Eigen::VectorXd b = Eigen::Map<const Eigen::Matrix<double, 10, 1>>(photoRatios.data());
  const Eigen::VectorXd n = nonNegativeLeastSquares(a, b);
  const double total = n.sum();
  if (!(total > 0)) return out;
  for (std::size_t k = 0; k < made.size(); ++k) out.ratios[std::size_t(made[k])] = n[Eigen::Index(k)] / total;
  out.residual = (a * n - b).norm() / b.norm();
  return out;
}

} // namespace

std::array<double, 10> unfoldBinRatios(const Eigen::Matrix<double, 10, 10>& kernel,
                                       const std::array<double, 10>& photoRatios) {
  const Unfolded u = unfold(kernel, photoRatios);
  return std::isfinite(u.residual) ? u.ratios : photoRatios;
}

SectionSizing fitSectionSizing(const ExemplarStats& stats, const ParticleFactory& factory, double voxelsPerPixel,
                               std::uint64_t seed) {
  // The kernel is in photo pixels: shapes of a few dozen voxels resolve it, whatever the volume's size.
  int largestSide = 1;
  for (const Particle2D& p : stats.particles) largestSide = std::max({largestSide, p.box.width, p.box.height});
  voxelsPerPixel = std::min(voxelsPerPixel, kKernelSide / largestSide);
  SectionSizing best;
  best.binRatios = stats.histogram.ratios;
  best.residual = INFINITY;
  for (int step = 0; step <= 10; ++step) {
    const double factor = 1 + 0.1 * step;
    const Unfolded u = unfold(measureSectionKernel(stats, factory, voxelsPerPixel, factor, seed), stats.histogram.ratios);
    if (u.residual < best.residual - 1e-9) best = {factor, u.ratios, u.residual};
  }
  if (!std::isfinite(best.residual)) best = {1, stats.histogram.ratios, 0};
  return best;
}

} // namespace solidtex
