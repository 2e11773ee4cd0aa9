#pragma once
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "common/Grid.h"

namespace solidtex {

/// A symmetric V-cycle of unsmoothed aggregation multigrid: the preconditioner Eigen's
/// ConjugateGradient takes for a voxel graph's Laplacian (symmetric positive definite, rows in
/// voxel order). Aggregates are 2x2x2 blocks of the grid split into their parts joined within the
/// block, so no coarse unknown couples regions the fine graph keeps apart (particles touching a
/// block at two places); coarse operators are Galerkin products, coarse corrections are scaled by
/// 1.5, smoothing is Gauss-Seidel within fixed chunks of rows (the same at any thread count), the
/// coarsest level a direct solve (Eigen's SimplicialLDLT).
class AggregationMultigrid {
public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

  AggregationMultigrid();
  ~AggregationMultigrid();
  AggregationMultigrid(AggregationMultigrid&&) noexcept;
  AggregationMultigrid& operator=(AggregationMultigrid&&) noexcept;

  /// The voxel of each row of the matrix compute() will get; required before each compute().
  void setVoxels(std::vector<Voxel> voxels);

  template <typename MatrixType>
  AggregationMultigrid& analyzePattern(const MatrixType&) {
    return *this;
  }
  template <typename MatrixType>
  AggregationMultigrid& factorize(const MatrixType& a) {
    return compute(a);
  }
  /// Builds the levels. `a` (compressed, row-major) is read again by solve(): it must outlive it.
  template <typename MatrixType>
  AggregationMultigrid& compute(const MatrixType& a) {
    build(Eigen::Map<const Matrix>(a.rows(), a.cols(), a.nonZeros(), a.outerIndexPtr(), a.innerIndexPtr(),
                                   a.valuePtr()));
    return *this;
  }
  Eigen::ComputationInfo info() const { return Eigen::Success; }

  /// One V-cycle from zero for a x = b. Uses buffers of its own: one call at a time.
  template <typename Rhs>
  Eigen::VectorXd solve(const Eigen::MatrixBase<Rhs>& b) const {
    return cycle(Eigen::VectorXd(b));
  }

  /// Levels built, the finest and the directly solved one included.
  int levels() const;

private:
  struct Hierarchy;
  void build(const Eigen::Map<const Matrix>& a);
  Eigen::VectorXd cycle(const Eigen::VectorXd& b) const;

  std::vector<Voxel> voxels_;
  std::unique_ptr<Hierarchy> hierarchy_;
};

}  // namespace solidtex
