#include "synthesis/detail/Pca.h"

#include <algorithm>

#include <Eigen/Eigenvalues>

namespace solidtex::synthesis {

double Pca::keptVariance() const {
  const double total = eigenvalues.cast<double>().sum();
  if (total <= 0) return 1.0;
  return std::min(1.0, double(eigenvalues.head(dims()).cast<double>().sum()) / total);
}

Eigen::MatrixXf Pca::projectAll(const Eigen::MatrixXf& samples) const {
  return basis.transpose() * (samples.colwise() - mean);
}

Pca fitPca(const Eigen::MatrixXf& samples, int dims) {
  const int D = int(samples.rows());
  const Eigen::Index M = samples.cols();
  const int d = std::clamp(dims, 1, D);
  Pca pca;
  const Eigen::MatrixXd x = samples.cast<double>();
  const Eigen::VectorXd mean = x.rowwise().mean();
  const Eigen::MatrixXd centred = x.colwise() - mean;
  const Eigen::MatrixXd cov = (centred * centred.transpose()) / double(std::max<Eigen::Index>(M, 1));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(cov);
  // Eigen sorts increasing; we want decreasing.
  const Eigen::VectorXd values = solver.eigenvalues().reverse();
  const Eigen::MatrixXd vectors = solver.eigenvectors().rowwise().reverse();
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

}  // namespace solidtex::synthesis
