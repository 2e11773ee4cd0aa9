#include <gtest/gtest.h>

#include "common/Random.h"
#include "synthesis/detail/Pca.h"

#include <Eigen/Eigenvalues>

using namespace solidtex;
using namespace solidtex::synthesis::detail;

namespace {

/// Correlated samples: D x M, most variance in a few directions.
Eigen::MatrixXf correlatedSamples(int D, int M, std::uint64_t seed) {
  Rng rng(seed);
  Eigen::MatrixXf mix(D, D);
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) mix(i, j) = float(uniform01(rng) - 0.5) / float(1 + j);
  Eigen::MatrixXf latent(D, M);
  for (int i = 0; i < D; ++i)
    for (int m = 0; m < M; ++m) latent(i, m) = float(uniform01(rng) - 0.5);
  Eigen::MatrixXf x = mix * latent;
  x.colwise() += Eigen::VectorXf::LinSpaced(D, 0.2f, 0.8f);
  return x;
}

}  // namespace

TEST(Pca, FullRoundTripIsExact) {
  const Eigen::MatrixXf x = correlatedSamples(12, 300, 1);
  const Pca pca = fitPca(x, 12);
  ASSERT_EQ(pca.dims(), 12);
  for (int m = 0; m < 300; m += 17)
    EXPECT_LT((pca.reconstruct(pca.project(x.col(m))) - x.col(m)).norm(), 1e-4f);
  EXPECT_NEAR(pca.keptVariance(), 1.0, 1e-9);
}

TEST(Pca, BasisIsOrthonormalAndSorted) {
  const Pca pca = fitPca(correlatedSamples(16, 400, 2), 6);
  EXPECT_LT((pca.basis.transpose() * pca.basis - Eigen::MatrixXf::Identity(6, 6)).norm(), 1e-4f);
  for (int i = 1; i < pca.eigenvalues.size(); ++i) EXPECT_GE(pca.eigenvalues[i - 1], pca.eigenvalues[i]);
}

TEST(Pca, TruncatedRoundTripLosesTheDroppedVariance) {
  const int D = 16, M = 2000, d = 5;
  const Eigen::MatrixXf x = correlatedSamples(D, M, 3);
  const Pca pca = fitPca(x, d);
  double err = 0;
  for (int m = 0; m < M; ++m) err += (pca.reconstruct(pca.project(x.col(m))) - x.col(m)).squaredNorm();
  err /= M;
  const double dropped = pca.eigenvalues.tail(D - d).cast<double>().sum();
  EXPECT_NEAR(err, dropped, 1e-3 * pca.eigenvalues.cast<double>().sum());
  // Projections of all samples agree with projectAll.
  const Eigen::MatrixXf all = pca.projectAll(x);
  EXPECT_LT((all.col(7) - pca.project(x.col(7))).norm(), 1e-5f);
}

// Fewer samples than dimensions: the basis comes from the Gram matrix and must span what the
// covariance's top eigenvectors span, with the same variances.
TEST(Pca, FewerSamplesThanDimensionsGiveTheCovariancesComponents) {
  const int D = 60, M = 25, d = 8;
  Eigen::MatrixXf x(D, M);
  solidtex::Rng rng(7);
  for (int j = 0; j < M; ++j)
    for (int i = 0; i < D; ++i) x(i, j) = float(solidtex::uniform01(rng)) * float(1 + i % 5);
  const Pca pca = fitPca(x, d);
  const Eigen::MatrixXd centred = (x.colwise() - x.rowwise().mean()).cast<double>();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> reference(centred * centred.transpose() / double(M));
  for (int c = 0; c < d; ++c) {
    const Eigen::VectorXd expected = reference.eigenvectors().col(D - 1 - c);
    EXPECT_NEAR(std::abs(expected.dot(pca.basis.col(c).cast<double>())), 1.0, 1e-4) << c;
    EXPECT_NEAR(pca.eigenvalues[c], reference.eigenvalues()[D - 1 - c],
                1e-4 * reference.eigenvalues()[D - 1]);
  }
  EXPECT_NEAR(pca.eigenvalues.cast<double>().sum(), reference.eigenvalues().sum(), 1e-3);
}

TEST(Pca, DimsAreClamped) {
  const Pca pca = fitPca(correlatedSamples(6, 50, 4), 20);
  EXPECT_EQ(pca.dims(), 6);
}
