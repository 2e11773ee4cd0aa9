#include <algorithm>

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "SeamStatistics.h"
#include "TestImages.h"
#include "common/Error.h"
#include "common/srgb.h"
#include "synthesis/synthesizeSolid.h"
#include "validation/continuousQuality.h"

using namespace solidtex;

namespace {

SynthesisOptions smallOptions(Method method) {
  SynthesisOptions o;
  o.method = method;
  o.size = 32;
  o.levels = 2;
  o.neighborhoods = {8, 4};
  o.iterations = 3;
  return o;
}

}  // namespace

TEST(Synthesize, TwoColorDiscsKeepTheirColorsAndFractions) {
  const cv::Vec3f a{0.9f, 0.8f, 0.3f}, b{0.1f, 0.2f, 0.6f};
  const cv::Mat ex = test::randomDiscs(64, 0.3, 21, a, b);
  int discPixels = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) discPixels += ex.at<cv::Vec3f>(y, x) == b;
  const double exemplarFraction = double(discPixels) / (64 * 64);

  const SynthesisResult r = synthesizeSolid(ex, smallOptions(Method::ChenWang));
  ASSERT_EQ(r.volume.color.size(), 32u * 32 * 32);
  ASSERT_EQ(r.volume.sourcePosition.size(), r.volume.color.size());
  auto lin = [](cv::Vec3f c) { return Rgb{srgbToLinear(c[0]), srgbToLinear(c[1]), srgbToLinear(c[2])}; };
  const Rgb la = lin(a), lb = lin(b);
  std::size_t inB = 0, other = 0;
  for (const Rgb& c : r.volume.color) {
    if (c == lb)
      ++inB;
    else if (c != la)
      ++other;
  }
  EXPECT_EQ(other, 0u);
  const double fraction = double(inB) / double(r.volume.color.size());
  EXPECT_GT(fraction, 0.0) << "exemplar " << exemplarFraction << " volume " << fraction;
}

// Isotropic discs: a solid of balls has every slice alike, with the same area fraction (Delesse).
// Without colour-histogram re-weighting the minority colour eroded to about 0.10 here.
TEST(Synthesize, TwoColorDiscFractionsMatchWithin5Percent) {
  const cv::Vec3f a{0.9f, 0.8f, 0.3f}, b{0.1f, 0.2f, 0.6f};
  const cv::Mat ex = test::randomDiscs(64, 0.3, 21, a, b);
  int discPixels = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) discPixels += ex.at<cv::Vec3f>(y, x) == b;
  const SynthesisResult r = synthesizeSolid(ex, smallOptions(Method::ChenWang));
  const Rgb lb{srgbToLinear(b[0]), srgbToLinear(b[1]), srgbToLinear(b[2])};
  std::size_t inB = 0;
  for (const Rgb& c : r.volume.color) inB += c == lb;
  EXPECT_NEAR(double(inB) / double(r.volume.color.size()), double(discPixels) / (64 * 64), 0.05);
}

// Skeletal voxels mix the three directions' rebuilt slices, so colours blend at the discs' edges: the
// share of the disc colour is measured along the line between the two colours.
TEST(Synthesize, SkeletalTwoColorDiscFractionsMatchWithin5Percent) {
  const cv::Vec3f a{0.9f, 0.8f, 0.3f}, b{0.1f, 0.2f, 0.6f};
  const cv::Mat ex = test::randomDiscs(64, 0.3, 21, a, b);
  int discPixels = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) discPixels += ex.at<cv::Vec3f>(y, x) == b;
  const SynthesisResult r = synthesizeSolid(ex, smallOptions(Method::Skeletal));
  ASSERT_EQ(r.volume.color.size(), 32u * 32 * 32);
  EXPECT_TRUE(r.volume.sourcePosition.empty());
  double share = 0;
  for (const Rgb& c : r.volume.color) share += (a[0] - linearToSrgb(c[0])) / (a[0] - b[0]);
  EXPECT_NEAR(share / double(r.volume.color.size()), double(discPixels) / (64 * 64), 0.05);
  ASSERT_TRUE(r.statistics.rebuildSeconds.has_value());
  EXPECT_EQ(r.statistics.levels.size(), 1u);  // the finest of the two levels is rebuilt
}

TEST(Synthesize, SameSeedSameOutputWithOneAndTwoThreads) {
  const cv::Mat ex = test::smoothImage(40, 40);
  for (Method m : {Method::ChenWang, Method::Kopf, Method::Skeletal}) {
    SynthesisOptions o = smallOptions(m);
    if (m == Method::Skeletal) o.distance = NeighborhoodDistance::Wavelet;
    o.size = 16;
    o.neighborhoods = {6, 4};
    o.iterations = 2;
    o.threads = 1;
    const SynthesisResult one = synthesizeSolid(ex, o);
    o.threads = 2;
    const SynthesisResult two = synthesizeSolid(ex, o);
    EXPECT_EQ(one.volume.color, two.volume.color) << methodName(m);
    EXPECT_EQ(one.volume.sourcePosition, two.volume.sourcePosition) << methodName(m);
    o.seed = 2;
    const SynthesisResult other = synthesizeSolid(ex, o);
    EXPECT_NE(one.volume.color, other.volume.color) << methodName(m);
  }
}

TEST(Synthesize, StatisticsHaveEnergiesTimesAndCoverage) {
  const cv::Mat ex = test::smoothImage(48, 48);
  SynthesisOptions o = smallOptions(Method::ChenWang);
  o.size = 16;
  std::vector<std::string> lines;
  std::vector<double> fractions;
  o.progress = [&](const std::string& l, double fraction) {
    lines.push_back(l);
    fractions.push_back(fraction);
  };
  const SynthesisResult r = synthesizeSolid(ex, o);
  const SynthesisStatistics& s = r.statistics;
  EXPECT_EQ(lines.size(), std::size_t(o.levels * o.iterations));
  // A 16^3 iteration costs 8 times an 8^3 one: the first of 3 iterations at 8^3 is 1/27 of the work.
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_NEAR(fractions.front(), 1.0 / (3 * 9), 1e-12);
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  ASSERT_EQ(s.levels.size(), 2u);
  EXPECT_EQ(s.levels[0].volumeSize, 8);
  EXPECT_EQ(s.levels[1].volumeSize, 16);
  EXPECT_EQ(s.levels[1].exemplarWidth, 48);
  for (const LevelStatistics& level : s.levels) {
    ASSERT_EQ(level.iterations.size(), 3u);
    for (const IterationStatistics& step : level.iterations) {
      EXPECT_GT(step.energy, 0.0);
      ASSERT_TRUE(step.positionCoverage.has_value());
      EXPECT_GT(*step.positionCoverage, 0.0);
      EXPECT_LE(*step.positionCoverage, 1.0);
    }
    EXPECT_GE(level.seconds, level.analysisSeconds);
    EXPECT_GT(level.pcaKeptVariance, 0.5);
    EXPECT_LE(level.pcaKeptVariance, 1.0 + 1e-9);
  }
  ASSERT_TRUE(s.indexCoverage.has_value());
  EXPECT_GT(*s.indexCoverage, 0.0);
  EXPECT_LE(*s.indexCoverage, 1.0);
  EXPECT_GE(s.seconds, s.levels[0].seconds + s.levels[1].seconds);
}

TEST(Synthesize, ExhaustiveSearchOnlyWithinTheBudget) {
  // 48x48 exemplar, 16^3 in two levels: level 1 has 289 neighbourhoods x 384 centres (111k
  // distances per iteration), level 2 has 2025 x 3072 (6.2M); both have fewer than 2048.
  const cv::Mat ex = test::smoothImage(48, 48);
  SynthesisOptions o = smallOptions(Method::ChenWang);
  o.size = 16;
  o.iterations = 1;
  const SynthesisResult all = synthesizeSolid(ex, o);
  EXPECT_EQ(all.statistics.levels[0].search, NeighborhoodSearch::Exhaustive);
  EXPECT_EQ(all.statistics.levels[1].search, NeighborhoodSearch::Exhaustive);
  o.exhaustiveBudget = 1e6;
  const SynthesisResult budget = synthesizeSolid(ex, o);
  EXPECT_EQ(budget.statistics.levels[0].search, NeighborhoodSearch::Exhaustive);
  EXPECT_EQ(budget.statistics.levels[1].search, NeighborhoodSearch::KCoherence);
  EXPECT_EQ(budget.statistics.levels[1].similarityLists, 0);  // 2025 neighbourhoods: exact sets

  o.approximateFrom = 2000;
  const SynthesisResult approximate = synthesizeSolid(ex, o);
  EXPECT_EQ(approximate.statistics.levels[1].similarityLists, 90);  // 2 sqrt(2025)
  EXPECT_EQ(approximate.statistics.levels[1].similarityProbes, 8);
  o.similaritySearch = SimilaritySearch::Exact;
  EXPECT_EQ(synthesizeSolid(ex, o).statistics.levels[1].similarityLists, 0);
}

TEST(Synthesize, KopfBlendsWithinTheColorRangeWithoutSources) {
  const cv::Mat ex = test::smoothImage(48, 48);
  SynthesisOptions o = smallOptions(Method::Kopf);
  o.size = 16;
  const SynthesisResult r = synthesizeSolid(ex, o);
  EXPECT_TRUE(r.volume.sourcePosition.empty());
  for (const Rgb& c : r.volume.color)
    for (float v : c) {
      EXPECT_GE(v, 0.0f);
      EXPECT_LE(v, 1.0f);
    }
  EXPECT_FALSE(r.statistics.levels[0].iterations[0].positionCoverage.has_value());
}

TEST(Synthesize, ControlMapMakesBrightPartsAppearMore) {
  const cv::Mat ex = test::smoothImage(48, 48);
  cv::Mat control(48, 48, CV_32FC1, cv::Scalar(0.0));
  control(cv::Rect(0, 0, 24, 48)).setTo(1.0);
  auto leftShare = [](const SynthesisResult& r) {
    std::size_t left = 0;
    for (const auto& p : r.volume.sourcePosition) left += p[0] < 24;
    return double(left) / double(r.volume.sourcePosition.size());
  };
  SynthesisOptions o = smallOptions(Method::ChenWang);
  o.size = 16;
  o.neighborhoods = {6, 4};
  const double plain = leftShare(synthesizeSolid(ex, o));
  o.control = control;
  const double controlled = leftShare(synthesizeSolid(ex, o));
  EXPECT_GT(controlled, plain + 0.05) << "plain " << plain << " controlled " << controlled;
}

// The photo methods synthesise on a torus at every stage (upsampling, slice neighbourhoods, the
// skeletal rebuild): where two copies meet, neighbouring voxels differ in colour as often as inside.
// The seam between two different volumes shows what a face that does not wrap would look like.
TEST(Synthesize, PhotoMethodsArePeriodic) {
  const cv::Mat ex = test::randomDiscs(64, 0.3, 21);
  for (Method m : {Method::ChenWang, Method::Skeletal}) {
    SynthesisOptions o = smallOptions(m);
    const SolidVolume one = synthesizeSolid(ex, o).volume;
    o.seed = 2;
    const SolidVolume other = synthesizeSolid(ex, o).volume;
    // the share of neighbour pairs whose colours differ: the discs' boundaries
    auto differ = [&](const SolidVolume& to) {
      return test::planeMeans(one.dims, 4, [&](const Voxel& a, const Voxel& b, int) {
        // across the wrap plane (b back at 0 on the pair's axis), `to` continues `one`
        const SolidVolume& next = b.x + b.y + b.z < a.x + a.y + a.z ? to : one;
        const Rgb& ca = one.color[one.dims.index(a)];
        const Rgb& cb = next.color[next.dims.index(b)];
        double d = 0;
        for (int c = 0; c < 3; ++c) d += (ca[c] - cb[c]) * (ca[c] - cb[c]);
        return d > 1e-4 ? 1.0 : 0.0;
      });
    };
    const test::PlaneMeans itself = differ(one), glued = differ(other);
    std::cout << methodName(m) << " wrapped: " << itself << "\n"
              << methodName(m) << " glued to another seed: " << glued << "\n";
    for (double wrap : itself.wrap) EXPECT_TRUE(itself.likeInterior(wrap)) << methodName(m) << " " << itself;
    EXPECT_NEAR(itself.wrapMean(), itself.mean(), itself.band()) << methodName(m);
    // one plane is too noisy at 32^3 to tell a seam for sure (skeletal blends colours); three do
    EXPECT_GT(glued.wrapMean(), glued.mean() + glued.band()) << methodName(m);
  }
}

TEST(Synthesize, BadInputThrowsInputError) {
  const cv::Mat ex = test::smoothImage(40, 40);
  SynthesisOptions o;
  o.size = 32;
  EXPECT_THROW(synthesizeSolid(test::smoothImage(20, 20), o), InputError);  // 5x5 at level 1 < 8
  o.size = 30;
  EXPECT_THROW(synthesizeSolid(ex, o), InputError);  // not a multiple of 4
  o.size = 32;
  o.neighborhoods = {8, 4};
  EXPECT_THROW(synthesizeSolid(ex, o), InputError);  // 2 sizes for 3 levels
  o.neighborhoods = {8, 6, 4};
  o.control = cv::Mat(20, 40, CV_32FC1, cv::Scalar(1.0));
  EXPECT_THROW(synthesizeSolid(ex, o), InputError);
  o.control.reset();
  o.size = 16;
  EXPECT_THROW(synthesizeSolid(ex, o), InputError);  // 4^3 coarsest volume < 8x8 neighbourhood
  EXPECT_THROW(synthesizeSolid(cv::Mat(), o), InputError);
  EXPECT_THROW(parseMethod("wavelet"), InputError);
  EXPECT_THROW(parseDistance("haar"), InputError);
  o.size = 64;
  o.neighborhoods = {10, 6, 4};
  o.distance = NeighborhoodDistance::Wavelet;
  EXPECT_THROW(synthesizeSolid(ex, o), InputError);  // 10x10 at level 1 holds 10 but not the 11 wavelet reads
  o.distance = NeighborhoodDistance::Rgb;
  o.neighborhoods = {8, 6, 4};
  o.size = 32;
  o.method = Method::Skeletal;
  o.waveletLevels = 3;
  EXPECT_THROW(synthesizeSolid(ex, o), InputError);  // no level left to optimise
  o.waveletLevels = 0;
  EXPECT_THROW(synthesizeSolid(ex, o), InputError);
  o.method = Method::ChenWang;
  try {
    o.size = 30;
    synthesizeSolid(ex, o);
    FAIL() << "a size that is not a multiple of 4 was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);  // one line on stderr
  }
}

TEST(Synthesize, RealExemplarChenWangKeepsColorsAndPatchesBetterThanKopf) {
  cv::Mat bgr = cv::imread(std::string(SOLIDTEX_DATA_DIR) + "/continuous/terra.png", cv::IMREAD_COLOR);
  ASSERT_FALSE(bgr.empty());
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  rgb.convertTo(rgb, CV_32F, 1.0 / 255.0);
  SynthesisOptions o;
  o.size = 32;
  o.iterations = 3;
  o.levels = 2;
  o.neighborhoods = {8, 4};
  const SynthesisResult cw = synthesizeSolid(rgb, o);
  o.method = Method::Kopf;
  const SynthesisResult kopf = synthesizeSolid(rgb, o);
  ContinuousQualityOptions measure;
  measure.distanceSides = {4, 8};
  const ContinuousQuality a = measureContinuousSolid(cw.volume, rgb, {}, measure),
                          b = measureContinuousSolid(kopf.volume, rgb, {}, measure);
  EXPECT_LT(a.colorHistogramDistance, b.colorHistogramDistance);
  EXPECT_LT(a.axis.patchDistance, b.axis.patchDistance);
  EXPECT_LT(a.oblique.patchDistance, b.oblique.patchDistance);
  ASSERT_TRUE(a.positions.has_value());
  EXPECT_FALSE(b.positions.has_value());  // kopf's voxels blend, they copy no one pixel
}
