#include "synthesis/detail/Pca.h"

#include <algorithm>
#include <utility>

#include <Eigen/Eigenvalues>

namespace solidtex::synthesis::detail {

double Pca::keptVariance() const {
  const double total = eigenvalues.cast<double>().sum();
  if (total <= 0) return 1.0;
  return std::min(1.0, double(eigenvalues.head(dims()).cast<double>().sum()) / total);
}

Eigen::MatrixXf Pca::projectAll(const Eigen::MatrixXf& samples) const {
  return basis.transpose() * (samples.colwise() - mean);
}

namespace {

// Eigenvalues (decreasing, all D) and eigenvectors (their columns) of the samples' covariance.
// With fewer samples than dimensions the covariance has rank below M, and the M x M Gram matrix
// has the same non-zero eigenvalues at a fraction of the cost (a 16x16 neighbourhood of wavelet
// features has 3072 dimensions, its coarse exemplar level a few hundred neighbourhoods).
std::pair<Eigen::VectorXd, Eigen::MatrixXd> covarianceEigen(const Eigen::MatrixXd& centred, int kept) {
  const Eigen::Index D = centred.rows(), M = std::max<Eigen::Index>(centred.cols(), 1);
  if (M < D && M >= kept) {
    const Eigen::MatrixXd gram = (centred.transpose() * centred) / double(M);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(gram);
    Eigen::VectorXd values = Eigen::VectorXd::Zero(D);
    values.head(M) = solver.eigenvalues().reverse();
    // Components of zero variance have no direction here: the covariance below gives them one.
    if (values[kept - 1] > 1e-12 * std::max(values[0], 1e-300)) {
      const Eigen::MatrixXd gramVectors = solver.eigenvectors().rowwise().reverse();
      Eigen::MatrixXd vectors(D, kept);
      for (int c = 0; c < kept; ++c) vectors.col(c) = (centred * gramVectors.col(c)).normalized();
      return {values, vectors};
    }
  }
  const Eigen::MatrixXd cov = (centred * centred.transpose()) / double(M);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(cov);
  // Eigen sorts increasing; we want decreasing.
  return {solver.eigenvalues().reverse(), solver.eigenvectors().rowwise().reverse()};
}

}  // namespace

Pca fitPca(const Eigen::MatrixXf& samples, int dims) {
  const int D = int(samples.rows());
  const int d = std::clamp(dims, 1, D);
  Pca pca;
  const Eigen::MatrixXd x = samples.cast<double>();
  const Eigen::VectorXd mean = x.rowwise().mean();
  const auto [values, vectors] = covarianceEigen(x.colwise() - mean, d);
  pca.mean = mean.cast<float>();
  pca.eigenvalues = values.cwiseMax(0.0).cast<float>();
  pca.basis = vectors.leftCols(d).cast<float>();
  // Fix each component's sign (largest-magnitude entry positive) so the basis is reproducible.
  for (int c = 0; c < d; ++c) {
    Eigen::Index arg;
    pca.basis.col(c).cwiseAbs().maxCoeff(&arg);
    if (pca.basis(arg, c) < 0) pca.basis.col(c) *= -1.0f;
  }
  return pca;
}

}  // namespace solidtex::synthesis::detail
