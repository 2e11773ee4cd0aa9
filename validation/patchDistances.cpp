#include "validation/patchDistances.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "common/Random.h"

namespace solidtex {
std::vector<double> nearestPatchDistances(const Eigen::MatrixXf& queries, const Eigen::MatrixXf& targets) {
  if (queries.rows() != targets.rows()) throw std::invalid_argument("patches of different sizes");
  std::vector<double> nearest(std::size_t(queries.cols()), 0.0);
  if (targets.cols() == 0) return nearest;
  const Eigen::VectorXf targetNorms = targets.colwise().squaredNorm().transpose();
  constexpr Eigen::Index chunk = 128;
  const Eigen::Index chunks = (queries.cols() + chunk - 1) / chunk;
  tbb::parallel_for(Eigen::Index(0), chunks, [&](Eigen::Index c) {
    const Eigen::Index begin = c * chunk, end = std::min(queries.cols(), begin + chunk);
    const Eigen::MatrixXf block = queries.middleCols(begin, end - begin);
    const Eigen::MatrixXf dots = targets.transpose() * block;
    for (Eigen::Index j = 0; j < end - begin; ++j) {
      Eigen::Index best = 0;
      (targetNorms - 2.0f * dots.col(j)).minCoeff(&best);
      // Found by the expansion, measured directly: its cancellation error would hide exact copies.
      const double d = (targets.col(best) - block.col(j)).cast<double>().squaredNorm();
      nearest[std::size_t(begin + j)] = std::sqrt(d / double(queries.rows()));
    }
  });
  return nearest;
}

double meanNearestPatchDistance(const Eigen::MatrixXf& queries, const Eigen::MatrixXf& targets) {
  const std::vector<double> d = nearestPatchDistances(queries, targets);
  return d.empty() ? 0.0 : std::accumulate(d.begin(), d.end(), 0.0) / double(d.size());
}

double slicedWasserstein(const Eigen::MatrixXf& a, const Eigen::MatrixXf& b, int directions,
                         std::uint64_t seed) {
  if (a.rows() != b.rows() || a.cols() != b.cols())
    throw std::invalid_argument("sliced Wasserstein needs equal patch sizes and counts");
  if (a.cols() == 0 || directions <= 0) return 0.0;
  Eigen::MatrixXf theta(a.rows(), directions);
  Rng rng(seed);
  for (int d = 0; d < directions; ++d) {
    for (Eigen::Index k = 0; k < a.rows(); ++k) theta(k, d) = float(standardNormal(rng));
    theta.col(d).normalize();
  }
  const Eigen::MatrixXf pa = theta.transpose() * a, pb = theta.transpose() * b;  // directions x count
  std::vector<double> perDirection(std::size_t(directions), 0.0);
  tbb::parallel_for(0, directions, [&](int d) {
    std::vector<float> x(std::size_t(a.cols())), y(std::size_t(a.cols()));
    for (Eigen::Index i = 0; i < a.cols(); ++i) x[std::size_t(i)] = pa(d, i), y[std::size_t(i)] = pb(d, i);
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    double sum = 0;
    for (std::size_t i = 0; i < x.size(); ++i) sum += std::abs(double(x[i]) - double(y[i]));
    perDirection[std::size_t(d)] = sum / double(x.size());
  });
  return std::accumulate(perDirection.begin(), perDirection.end(), 0.0) / double(directions);
}

}  // namespace solidtex
