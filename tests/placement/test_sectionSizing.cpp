#include <gtest/gtest.h>

#include <numeric>

#include "common/Error.h"
#include "placement/sectionSizing.h"

namespace solidtex {
namespace {

TEST(NonNegativeLeastSquares, RecoversANonNegativeSolution) {
  Eigen::MatrixXd a(6, 4);
  a << 1, 2, 0, 1,  //
      0, 1, 3, 1,   //
      2, 0, 1, 0,   //
      1, 1, 1, 4,   //
      0, 3, 0, 2,   //
      5, 0, 2, 1;
  const Eigen::Vector4d truth(0.5, 0, 2, 1.25);
  const Eigen::VectorXd x = nonNegativeLeastSquares(a, a * truth);
  EXPECT_LT((x - truth).norm(), 1e-9);
}

TEST(NonNegativeLeastSquares, ClampsWhereLeastSquaresWouldGoNegative) {
  const Eigen::VectorXd x = nonNegativeLeastSquares(Eigen::MatrixXd::Identity(2, 2), Eigen::Vector2d(1, -1));
  EXPECT_NEAR(x[0], 1, 1e-12);
  EXPECT_EQ(x[1], 0);
}

// Spheres of class j cut by random planes give section areas spread evenly up to their largest
// section: a triangular kernel. Sections of known 3D shares through it unfold back to those shares.
TEST(UnfoldBinRatios, RecoversTheSharesBehindATriangularKernel) {
  Eigen::Matrix<double, 10, 10> kernel = Eigen::Matrix<double, 10, 10>::Zero();
  for (int j = 0; j < 10; ++j)
    for (int b = 0; b <= j; ++b) kernel(b, j) = 0.1;  // hits grow as (j+1)/10, spread evenly over j+1 bins
  const std::array<double, 10> truth = {0.05, 0.0, 0.1, 0.2, 0.05, 0.15, 0.1, 0.2, 0.05, 0.1};
  const Eigen::Matrix<double, 10, 1> sections = kernel * Eigen::Map<const Eigen::Matrix<double, 10, 1>>(truth.data());
  std::array<double, 10> photo{};
  for (int b = 0; b < 10; ++b) photo[std::size_t(b)] = sections[b] / sections.sum();
  const std::array<double, 10> unfolded = unfoldBinRatios(kernel, photo);
  for (int b = 0; b < 10; ++b) EXPECT_NEAR(unfolded[std::size_t(b)], truth[std::size_t(b)], 1e-9) << "bin " << b;
  // The small sections came mostly from large particles: the 3D shares lean larger than the photo's.
  EXPECT_LT(unfolded[0], photo[0]);
}

TEST(Sizing, ParsesNames) {
  EXPECT_EQ(parseSizing("bbox"), Sizing::Bbox);
  EXPECT_EQ(parseSizing(sizingName(Sizing::Sections)), Sizing::Sections);
  EXPECT_THROW(parseSizing("volume"), InputError);
}

} // namespace
} // namespace solidtex
