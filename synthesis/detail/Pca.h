#pragma once
#include <Eigen/Core>

namespace solidtex::synthesis::detail {

/// Principal component analysis of column vectors: y = basisᵀ (x - mean), x ≈ mean + basis y.
struct Pca {
  Eigen::VectorXf mean;         ///< D
  Eigen::MatrixXf basis;        ///< D x d, orthonormal columns by decreasing variance
  Eigen::VectorXf eigenvalues;  ///< all D variances, decreasing

  int inputDims() const { return int(mean.size()); }
  int dims() const { return int(basis.cols()); }
  /// Share of the total variance the kept components explain, in [0,1].
  double keptVariance() const;
  /// Reduces one vector (D) to its d coefficients.
  Eigen::VectorXf project(const Eigen::VectorXf& x) const { return basis.transpose() * (x - mean); }
  /// Back from d coefficients to D.
  Eigen::VectorXf reconstruct(const Eigen::VectorXf& y) const { return mean + basis * y; }
  /// Reduces every column of a D x M matrix: d x M.
  Eigen::MatrixXf projectAll(const Eigen::MatrixXf& samples) const;
};

/// Fits a PCA keeping min(dims, D) components to the columns of `samples` (D x M, M >= 1).
/// Covariance is accumulated in double precision; deterministic.
Pca fitPca(const Eigen::MatrixXf& samples, int dims);

}  // namespace solidtex::synthesis::detail
