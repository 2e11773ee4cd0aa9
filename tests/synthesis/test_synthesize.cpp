#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "synthesis/ColorSpace.h"
#include "synthesis/synthesizeSolid.h"
#include "TestImages.h"

using namespace solidtex;

namespace {

SynthesisOptions smallOptions(Method method) {
  SynthesisOptions o;
  o.method = method;
  o.size = 32;
  o.levels = 2;
  o.neighborhoods = {8, 4};
  o.iterations = 3;
  o.measureOptions.axisSamples = 300;
  o.measureOptions.obliqueSamples = 300;
  return o;
}

} // namespace

TEST(Synthesize, TwoColourDiscsKeepTheirColoursAndFractions) {
  const cv::Vec3f a{0.9f, 0.8f, 0.3f}, b{0.1f, 0.2f, 0.6f};
  const cv::Mat ex = test::randomDiscs(64, 0.3, 21, a, b);
  int discPixels = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) discPixels += ex.at<cv::Vec3f>(y, x) == b;
  const double exemplarFraction = double(discPixels) / (64 * 64);

  const SynthesisResult r = synthesizeSolid(ex, smallOptions(Method::ChenWang));
  ASSERT_EQ(r.volume.color.size(), 32u * 32 * 32);
  ASSERT_EQ(r.volume.sourcePosition.size(), r.volume.color.size());
  auto lin = [](cv::Vec3f c) { return Rgb{synthesis::srgbToLinearChannel(c[0]), synthesis::srgbToLinearChannel(c[1]), synthesis::srgbToLinearChannel(c[2])}; };
  const Rgb la = lin(a), lb = lin(b);
  std::size_t inB = 0, other = 0;
  for (const Rgb& c : r.volume.color) {
    if (c == lb) ++inB;
    else if (c != la) ++other;
  }
  EXPECT_EQ(other, 0u);
  const double fraction = double(inB) / double(r.volume.color.size());
  EXPECT_GT(fraction, 0.0) << "exemplar " << exemplarFraction << " volume " << fraction;
}

// Isotropic discs: a solid of balls has every slice alike, with the same area fraction (Delesse).
// Without colour-histogram re-weighting the minority colour eroded to about 0.10 here.
TEST(Synthesize, TwoColourDiscFractionsMatchWithin5Percent) {
  const cv::Vec3f a{0.9f, 0.8f, 0.3f}, b{0.1f, 0.2f, 0.6f};
  const cv::Mat ex = test::randomDiscs(64, 0.3, 21, a, b);
  int discPixels = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) discPixels += ex.at<cv::Vec3f>(y, x) == b;
  const SynthesisResult r = synthesizeSolid(ex, smallOptions(Method::ChenWang));
  const Rgb lb{synthesis::srgbToLinearChannel(b[0]), synthesis::srgbToLinearChannel(b[1]), synthesis::srgbToLinearChannel(b[2])};
  std::size_t inB = 0;
  for (const Rgb& c : r.volume.color) inB += c == lb;
  EXPECT_NEAR(double(inB) / double(r.volume.color.size()), double(discPixels) / (64 * 64), 0.05);
}

TEST(Synthesize, SameSeedSameOutputWithOneAndTwoThreads) {
  const cv::Mat ex = test::smoothImage(40, 40);
  for (Method m : {Method::ChenWang, Method::Kopf}) {
    SynthesisOptions o = smallOptions(m);
    o.size = 16;
    o.neighborhoods = {6, 4};
    o.iterations = 2;
    o.measure = false;
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

TEST(Synthesize, ReportHasEnergiesTimesAndQuality) {
  const cv::Mat ex = test::smoothImage(48, 48);
  SynthesisOptions o = smallOptions(Method::ChenWang);
  o.size = 16;
  std::vector<std::string> lines;
  o.progress = [&](const std::string& l) { lines.push_back(l); };
  const SynthesisResult r = synthesizeSolid(ex, o);
  EXPECT_EQ(lines.size(), std::size_t(o.levels * o.iterations));
  ASSERT_EQ(r.report["levelReports"].size(), 2u);
  EXPECT_EQ(r.report["levelReports"][1]["iterations"].size(), 3u);
  EXPECT_TRUE(r.report["levelReports"][0]["iterations"][0].contains("energy"));
  EXPECT_TRUE(r.report["levelReports"][0].contains("seconds"));
  for (const char* key : {"energyAxis", "energyOblique", "positionCoverage", "positionFlatness", "colorHistogramDistance"})
    EXPECT_TRUE(r.report["quality"].contains(key)) << key;
  EXPECT_GT(r.report["peakMemoryMiB"].get<double>(), 0.0);
}

TEST(Synthesize, ExhaustiveSearchOnlyWithinTheBudget) {
  // 48x48 exemplar, 16^3 in two levels: level 1 has 289 neighbourhoods x 384 centres (111k
  // distances per iteration), level 2 has 2025 x 3072 (6.2M); both have fewer than 2048.
  const cv::Mat ex = test::smoothImage(48, 48);
  SynthesisOptions o = smallOptions(Method::ChenWang);
  o.size = 16;
  o.iterations = 1;
  o.measure = false;
  const SynthesisResult all = synthesizeSolid(ex, o);
  EXPECT_EQ(all.report["levelReports"][0]["search"], "exhaustive");
  EXPECT_EQ(all.report["levelReports"][1]["search"], "exhaustive");
  o.exhaustiveBudget = 1e6;
  const SynthesisResult budget = synthesizeSolid(ex, o);
  EXPECT_EQ(budget.report["levelReports"][0]["search"], "exhaustive");
  EXPECT_EQ(budget.report["levelReports"][1]["search"], "k-coherence");
}

TEST(Synthesize, KopfBlendsWithinTheColourRangeWithoutSources) {
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
  EXPECT_TRUE(r.report["quality"].contains("positionCoverage"));
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
  o.measure = false;
  const double plain = leftShare(synthesizeSolid(ex, o));
  o.control = control;
  const double controlled = leftShare(synthesizeSolid(ex, o));
  EXPECT_GT(controlled, plain + 0.05) << "plain " << plain << " controlled " << controlled;
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
  try {
    o.size = 30;
    synthesizeSolid(ex, o);
    FAIL() << "a size that is not a multiple of 4 was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);  // one line on stderr
  }
}

TEST(Synthesize, RealExemplarChenWangKeepsColoursBetterThanKopf) {
  cv::Mat bgr = cv::imread(std::string(SOLIDTEX_DATA_DIR) + "/continuous/terra.png", cv::IMREAD_COLOR);
  ASSERT_FALSE(bgr.empty());
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  rgb.convertTo(rgb, CV_32F, 1.0 / 255.0);
  SynthesisOptions o;
  o.size = 32;
  o.iterations = 3;
  o.measureOptions.axisSamples = 600;
  o.measureOptions.obliqueSamples = 600;
  o.levels = 2;
  o.neighborhoods = {8, 4};
  const SynthesisResult cw = synthesizeSolid(rgb, o);
  o.method = Method::Kopf;
  const SynthesisResult kopf = synthesizeSolid(rgb, o);
  // Slice energy is reported, not asserted: Kopf's blur scores lower on it (see the synthesis report).
  EXPECT_GT(cw.report["quality"]["positionCoverage"].get<double>(), kopf.report["quality"]["positionCoverage"].get<double>());
  EXPECT_LT(cw.report["quality"]["colorHistogramDistance"].get<double>(), kopf.report["quality"]["colorHistogramDistance"].get<double>());
}
