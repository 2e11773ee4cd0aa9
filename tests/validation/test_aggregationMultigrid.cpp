#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>

#include "validation/aggregationMultigrid.h"

namespace solidtex {
namespace {

using Matrix = AggregationMultigrid::Matrix;

struct GridSystem {
  Matrix a;
  std::vector<Voxel> voxels;
};

// A diffusion operator on an n^3 grid pierced by columns along z, with conductances spread over a
// factor of 20 and the x faces held by reservoirs: symmetric positive definite, well above the
// size solved directly, so the cycle has several levels.
GridSystem piercedGrid(int n) {
  const Dims d{n, n, n};
  const auto in = [](const Voxel& v) { return !(v.x % 4 == 1 && v.y % 4 == 1); };
  std::vector<int> unknown(d.count(), -1);
  GridSystem s;
  for (std::size_t i = 0; i < d.count(); ++i)
    if (in(d.voxel(i))) unknown[i] = int(s.voxels.size()), s.voxels.push_back(d.voxel(i));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> conductance(0.05, 1.0);
  std::vector<double> diagonal(s.voxels.size(), 0.0);
  std::vector<Eigen::Triplet<double, int>> entries;
  for (std::size_t row = 0; row < s.voxels.size(); ++row) {
    const Voxel v = s.voxels[row];
    if (v.x == 0 || v.x == n - 1) diagonal[row] += 2;
    for (const Voxel& w : {Voxel{v.x + 1, v.y, v.z}, Voxel{v.x, v.y + 1, v.z}, Voxel{v.x, v.y, v.z + 1}}) {
      if (!d.contains(w.x, w.y, w.z) || unknown[d.index(w)] < 0) continue;
      const int col = unknown[d.index(w)];
      const double g = conductance(rng);
      entries.emplace_back(int(row), col, -g);
      entries.emplace_back(col, int(row), -g);
      diagonal[row] += g;
      diagonal[std::size_t(col)] += g;
    }
  }
  for (std::size_t row = 0; row < diagonal.size(); ++row)
    entries.emplace_back(int(row), int(row), diagonal[row]);
  s.a.resize(int(s.voxels.size()), int(s.voxels.size()));
  s.a.setFromTriplets(entries.begin(), entries.end());
  return s;
}

TEST(AggregationMultigrid, CycleIsSymmetricPositiveDefinite) {
  const GridSystem s = piercedGrid(36);
  AggregationMultigrid cycle;
  cycle.setVoxels(s.voxels);
  cycle.compute(s.a);
  EXPECT_GE(cycle.levels(), 3);
  std::mt19937 rng(3);
  std::normal_distribution<double> normal;
  const auto random = [&] {
    return Eigen::VectorXd(Eigen::VectorXd::NullaryExpr(s.a.rows(), [&] { return normal(rng); }));
  };
  for (int trial = 0; trial < 4; ++trial) {
    const Eigen::VectorXd u = random(), v = random();
    const Eigen::VectorXd bu = cycle.solve(u), bv = cycle.solve(v);
    EXPECT_NEAR(u.dot(bv), v.dot(bu), 1e-11 * u.norm() * bv.norm());  // CG needs a symmetric preconditioner
    EXPECT_GT(u.dot(bu), 0.0);
  }
}

TEST(AggregationMultigrid, PreconditionedCgReachesTheDirectSolutionInFewIterations) {
  const GridSystem s = piercedGrid(28);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(s.a.rows(), -1.0, 2.0);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> direct{Eigen::SparseMatrix<double>(s.a)};
  const Eigen::VectorXd exact = direct.solve(b);

  Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper, AggregationMultigrid> multigrid;
  multigrid.setTolerance(1e-10);
  multigrid.preconditioner().setVoxels(s.voxels);
  multigrid.compute(s.a);
  const Eigen::VectorXd x = multigrid.solve(b);
  EXPECT_LT((x - exact).norm(), 1e-8 * exact.norm());

  Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper> jacobi;
  jacobi.setTolerance(1e-10);
  jacobi.compute(s.a);
  const Eigen::VectorXd y = jacobi.solve(b);
  ASSERT_EQ(jacobi.info(), Eigen::Success);
  EXPECT_LT((y - exact).norm(), 1e-8 * exact.norm());
  EXPECT_LT(multigrid.iterations() * 4, jacobi.iterations());
}

}  // namespace
}  // namespace solidtex
