#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "common/Random.h"
#include "common/srgb.h"
#include "validation/continuousQuality.h"
#include "validation/patchDistances.h"
#include "validation/slicePatches.h"

namespace solidtex {
namespace {

// Two flat colours: random discs (radius 3-6) on a background until `fraction` of the pixels are discs.
cv::Mat discs(int size, double fraction, std::uint64_t seed) {
  const cv::Vec3f background{0.9f, 0.8f, 0.3f}, disc{0.1f, 0.2f, 0.6f};
  cv::Mat image(size, size, CV_32FC3, background);
  Rng rng(seed);
  while (cv::mean(image)[0] > 0.9 - fraction * 0.8) {
    const cv::Point centre(int(uniformIndex(rng, std::uint64_t(size))),
                           int(uniformIndex(rng, std::uint64_t(size))));
    cv::circle(image, centre, 3 + int(uniformIndex(rng, 4)), disc, cv::FILLED);
  }
  return image;
}

// Every slice z = k is the image: a sharp solid whose z slices are the exemplar itself.
SolidVolume extrusion(const cv::Mat& srgb, int depth) {
  SolidVolume v;
  v.dims = {srgb.cols, srgb.rows, depth};
  v.color.resize(v.dims.count());
  for (int k = 0; k < depth; ++k)
    for (int j = 0; j < srgb.rows; ++j)
      for (int i = 0; i < srgb.cols; ++i) {
        const cv::Vec3f& c = srgb.at<cv::Vec3f>(j, i);
        v.color[v.dims.index(i, j, k)] = {srgbToLinear(c[0]), srgbToLinear(c[1]), srgbToLinear(c[2])};
      }
  return v;
}

SolidVolume constantSolid(const Dims& dims, const cv::Scalar& srgb) {
  SolidVolume v;
  v.dims = dims;
  v.color.assign(dims.count(), Rgb{srgbToLinear(float(srgb[0])), srgbToLinear(float(srgb[1])),
                                   srgbToLinear(float(srgb[2]))});
  return v;
}

Eigen::MatrixXf randomColumns(int rows, int cols, std::uint64_t seed) {
  Rng rng(seed);
  Eigen::MatrixXf m(rows, cols);
  for (int j = 0; j < cols; ++j)
    for (int i = 0; i < rows; ++i) m(i, j) = float(uniform01(rng));
  return m;
}

TEST(PatchDistances, NearestIsTheExactMinimumOfRmsDistances) {
  const Eigen::MatrixXf queries = randomColumns(12, 40, 1), targets = randomColumns(12, 300, 2);
  const std::vector<double> nearest = nearestPatchDistances(queries, targets);
  for (int q = 0; q < queries.cols(); ++q) {
    double best = 1e30;
    for (int t = 0; t < targets.cols(); ++t)
      best = std::min(best, double((queries.col(q) - targets.col(t)).squaredNorm()) / 12.0);
    EXPECT_NEAR(nearest[std::size_t(q)], std::sqrt(best), 1e-6);
  }
  EXPECT_DOUBLE_EQ(meanNearestPatchDistance(targets.leftCols(10), targets), 0.0);
}

TEST(PatchDistances, SlicedWassersteinIsZeroForTheSameSetAndMeasuresAShift) {
  const Eigen::MatrixXf a = randomColumns(12, 500, 3);
  Eigen::MatrixXf reversed = a.rowwise().reverse();
  EXPECT_DOUBLE_EQ(slicedWasserstein(a, reversed, 32, 7), 0.0);
  // Shifting every patch by t moves each projection by theta . t: the mean of |theta . t| over unit
  // directions in 12 dimensions is |t| * Gamma(6) / (sqrt(pi) * Gamma(6.5)) = 0.2255 |t|.
  const Eigen::VectorXf t = Eigen::VectorXf::Constant(12, 0.1f);
  const Eigen::MatrixXf shifted = a.colwise() + t;
  const double expected = double(t.norm()) * std::tgamma(6.0) / (std::sqrt(M_PI) * std::tgamma(6.5));
  EXPECT_NEAR(slicedWasserstein(a, shifted, 20000, 7), expected, 0.03 * expected);
}

// The image's colour is (x, y, 0) / 20, so a patch's first pixel says where the patch lies.
TEST(SlicePatches, ImagePatchesTakeEveryPositionOnceAndAverageBlocks) {
  cv::Mat image(20, 20, CV_32FC3);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) image.at<cv::Vec3f>(y, x) = {float(x) / 20, float(y) / 20, 0.0f};
  const PatchGeometry g{3, 2};
  ASSERT_EQ(patchPositions(image.size(), g), 15 * 15);
  const Eigen::MatrixXf all = imagePatches(image, g, 1000, 5);
  ASSERT_EQ(all.cols(), 225);
  std::set<int> positions;
  for (int p = 0; p < all.cols(); ++p) {
    // Block (c, r) of the patch at (x0, y0) averages pixels x0 + 2c and x0 + 2c + 1: (x0 + 2c + 0.5) / 20.
    const int x0 = int(std::lround(all(0, p) * 20 - 0.5)), y0 = int(std::lround(all(1, p) * 20 - 0.5));
    positions.insert(15 * y0 + x0);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(all(3 * (3 * r + c), p), (x0 + 2 * c + 0.5) / 20, 1e-6);
        EXPECT_NEAR(all(3 * (3 * r + c) + 1, p), (y0 + 2 * r + 0.5) / 20, 1e-6);
      }
  }
  EXPECT_EQ(positions.size(), 225u);
  EXPECT_EQ(*positions.begin(), 0);
  EXPECT_EQ(*positions.rbegin(), 224);
}

// On a volume whose sRGB colour is (x, y, z) / n, neighbouring patch pixels differ by one voxel step
// along the plane: 1/n in one channel on axis slices, a unit vector over n on oblique planes.
TEST(SlicePatches, SlicesStepOneVoxelAlongTheirPlane) {
  const int n = 40;
  SrgbVolume v{{n, n, n}, {}};
  v.rgb.resize(v.dims.count() * 3);
  for (std::size_t i = 0; i < v.dims.count(); ++i) {
    const Voxel p = v.dims.voxel(i);
    v.rgb[3 * i] = float(p.x) / n, v.rgb[3 * i + 1] = float(p.y) / n, v.rgb[3 * i + 2] = float(p.z) / n;
  }
  const PatchGeometry g{6, 1};
  for (const Eigen::MatrixXf& patches : {axisSlicePatches(v, g, 60, 1), obliqueSlicePatches(v, g, 60, 2)})
    for (int p = 0; p < patches.cols(); ++p)
      for (int r = 0; r < g.side; ++r)
        for (int c = 0; c + 1 < g.side; ++c) {
          const Eigen::Vector3f a = patches.col(p).segment<3>(3 * (g.side * r + c)),
                                b = patches.col(p).segment<3>(3 * (g.side * r + c + 1));
          EXPECT_NEAR((b - a).norm(), 1.0 / n, 1e-5);
          EXPECT_GE(a.minCoeff(), 0.0f);
          EXPECT_LE(a.maxCoeff(), float(n - 1) / n + 1e-6f);
        }
}

TEST(ContinuousQuality, TheExemplarAsReferenceScoresZero) {
  const cv::Mat exemplar = discs(48, 0.3, 1);
  const ContinuousQuality q = measureContinuousSolid(extrusion(exemplar, 48), exemplar, exemplar);
  ASSERT_TRUE(q.reference.has_value());
  // Identical patches, found by a float expansion of the distance: zero up to its rounding.
  EXPECT_NEAR(q.reference->coherence, 0.0, 1e-6);
  EXPECT_NEAR(q.reference->completeness, 0.0, 1e-6);
  EXPECT_NEAR(q.reference->patchDistance, 0.0, 1e-6);
  EXPECT_EQ(q.reference->patchDistances.size(), 6u);  // sides 4, 8, 16 at scales 1 and 2
  EXPECT_DOUBLE_EQ(*q.referenceColorHistogramDistance, 0.0);
}

// A solid of the exemplar's mean colour is close to some exemplar patches (coherent) but leaves the
// discs out: completeness and patch distance say so.
TEST(ContinuousQuality, AConstantSolidIsLessCompleteThanTheExtrusion) {
  const cv::Mat exemplar = discs(48, 0.3, 2);
  const ContinuousQuality sharp = measureContinuousSolid(extrusion(exemplar, 48), exemplar);
  const ContinuousQuality flat =
      measureContinuousSolid(constantSolid({48, 48, 48}, cv::mean(exemplar)), exemplar);
  for (auto member : {&ContinuousQuality::axis, &ContinuousQuality::oblique}) {
    EXPECT_GT((flat.*member).completeness, 1.5 * (sharp.*member).completeness);
    EXPECT_GT((flat.*member).patchDistance, 1.5 * (sharp.*member).patchDistance);
  }
  EXPECT_GT(flat.colorHistogramDistance, 0.9);
}

TEST(ContinuousQuality, ABlurredSolidScoresWorseThanTheSharpOne) {
  const cv::Mat exemplar = discs(48, 0.3, 3);
  cv::Mat blurred;
  cv::GaussianBlur(exemplar, blurred, cv::Size(), 1.5, 1.5, cv::BORDER_REFLECT);
  const ContinuousQuality sharp = measureContinuousSolid(extrusion(exemplar, 48), exemplar);
  const ContinuousQuality soft = measureContinuousSolid(extrusion(blurred, 48), exemplar);
  for (auto member : {&ContinuousQuality::axis, &ContinuousQuality::oblique}) {
    EXPECT_GT((soft.*member).completeness, (sharp.*member).completeness);
    EXPECT_GT((soft.*member).bidirectional(), (sharp.*member).bidirectional());
    EXPECT_GT((soft.*member).patchDistance, (sharp.*member).patchDistance);
  }
}

TEST(ContinuousQuality, SameFiguresAtAnyThreadCount) {
  const cv::Mat exemplar = discs(40, 0.3, 5);
  const SolidVolume solid = extrusion(discs(40, 0.3, 6), 40);
  ContinuousQuality one, two;
  {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = measureContinuousSolid(solid, exemplar, exemplar);
  }
  {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    two = measureContinuousSolid(solid, exemplar, exemplar);
  }
  EXPECT_EQ(one.axis.coherence, two.axis.coherence);
  EXPECT_EQ(one.oblique.completeness, two.oblique.completeness);
  EXPECT_EQ(one.oblique.patchDistance, two.oblique.patchDistance);
  EXPECT_EQ(one.reference->patchDistance, two.reference->patchDistance);
}

// Large exemplars (a 1024^2 photo has a million patches of each size) are sampled, not taken whole.
TEST(ContinuousQuality, PatchSetsAreCappedAtTheAskedCount) {
  const cv::Mat exemplar = discs(48, 0.3, 10);
  ContinuousQualityOptions o;
  o.patches = 500;
  const ContinuousQuality q = measureContinuousSolid(extrusion(exemplar, 48), exemplar, {}, o);
  ASSERT_EQ(q.axis.patchDistances.size(), 6u);
  for (const PatchDistance& d : q.axis.patchDistances) {
    const int positions = (48 - d.side * d.scale + 1) * (48 - d.side * d.scale + 1);
    EXPECT_EQ(d.patches, std::min(500, positions)) << "side " << d.side << " scale " << d.scale;
  }
}

TEST(ContinuousQuality, ASolidTooSmallForThePatchesIsAnInputError) {
  const cv::Mat exemplar = discs(32, 0.3, 7);
  EXPECT_THROW(measureContinuousSolid(constantSolid({8, 8, 8}, cv::mean(exemplar)), exemplar), InputError);
  EXPECT_THROW(measureContinuousSolid(SolidVolume{}, exemplar), InputError);
}

TEST(ContinuousQuality, TextureMeasuresSeeTheExemplarAsZeroAndBlurAsWorse) {
  const cv::Mat exemplar = discs(48, 0.3, 8), second = discs(48, 0.3, 9);
  cv::Mat blurred;
  cv::GaussianBlur(second, blurred, cv::Size(), 1.5, 1.5, cv::BORDER_REFLECT);
  const TextureQuality same = measureTexture(exemplar, exemplar, exemplar);
  EXPECT_NEAR(same.texture.bidirectional(), 0.0, 1e-6);
  EXPECT_NEAR(same.texture.patchDistance, 0.0, 1e-6);
  EXPECT_DOUBLE_EQ(same.colorHistogramDistance, 0.0);
  const TextureQuality sharp = measureTexture(second, exemplar);
  const TextureQuality soft = measureTexture(blurred, exemplar);
  EXPECT_GT(soft.texture.completeness, sharp.texture.completeness);
  EXPECT_GT(soft.texture.patchDistance, sharp.texture.patchDistance);
}

TEST(ContinuousQuality, ColorHistogramDistance) {
  const std::vector<float> a{0.1f, 0.1f, 0.1f, 0.9f, 0.9f, 0.9f}, b{0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f};
  EXPECT_DOUBLE_EQ(colorHistogramDistance(a.data(), 2, a.data(), 2), 0.0);
  EXPECT_NEAR(colorHistogramDistance(a.data(), 2, b.data(), 2), 0.5, 1e-12);
}

TEST(ContinuousQuality, PositionHistogramStats) {
  const auto even = positionHistogramStats({0, 1, 2, 3, 3, 2, 1, 0}, 4);
  EXPECT_DOUBLE_EQ(even.coverage, 1.0);
  EXPECT_NEAR(even.flatness, 1.0, 1e-12);
  EXPECT_NEAR(even.variation, 0.0, 1e-12);
  const auto one = positionHistogramStats({2, 2, 2, 2}, 4);
  EXPECT_DOUBLE_EQ(one.coverage, 0.25);
  EXPECT_NEAR(one.flatness, 0.0, 1e-12);
  const auto half = positionHistogramStats({0, 1, 0, 1}, 4);
  EXPECT_DOUBLE_EQ(half.coverage, 0.5);
  EXPECT_NEAR(half.flatness, 0.5, 1e-12);
}

}  // namespace
}  // namespace solidtex
