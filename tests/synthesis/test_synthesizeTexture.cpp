#include <gtest/gtest.h>

#include "TestImages.h"
#include "common/Error.h"
#include "synthesis/synthesizeTexture.h"

using namespace solidtex;

namespace {

TextureSynthesisOptions smallOptions(TextureMethod method) {
  TextureSynthesisOptions o;
  o.method = method;
  o.width = o.height = 32;
  o.levels = 2;
  o.neighborhoods = {6, 4};
  o.iterations = 4;
  return o;
}

// A tile of random colours repeated `repeats` x `repeats` times.
cv::Mat tiledExemplar(int tile, int repeats, std::uint64_t seed) {
  const cv::Mat one = test::randomImage(tile, tile, seed);
  cv::Mat out;
  cv::repeat(one, repeats, repeats, out);
  return out;
}

// Whether the tile x tile window at (x, y) of the periodic image equals the tile at some cyclic shift.
bool isShiftedTile(const cv::Mat& image, const cv::Mat& exemplar, int tile, int x, int y) {
  for (int sy = 0; sy < tile; ++sy)
    for (int sx = 0; sx < tile; ++sx) {
      bool same = true;
      for (int j = 0; j < tile && same; ++j)
        for (int i = 0; i < tile && same; ++i) {
          const cv::Vec3f a = image.at<cv::Vec3f>((y + j) % image.rows, (x + i) % image.cols);
          const cv::Vec3f b = exemplar.at<cv::Vec3f>(sy + j, sx + i);
          same = cv::norm(a - b) < 1e-4;
        }
      if (same) return true;
    }
  return false;
}

}  // namespace

TEST(SynthesizeTexture, SkeletalRebuildsTilesOfARepeatedTile) {
  const int tile = 8;
  const cv::Mat exemplar = tiledExemplar(tile, 4, 3);
  TextureSynthesisOptions o = smallOptions(TextureMethod::Skeletal);
  o.levels = 3;  // two optimised levels: a random 16x16 start alone does not settle into the tiling
  o.neighborhoods = {6};
  const TextureSynthesisResult r = synthesizeTexture(exemplar, o);
  ASSERT_EQ(r.image.cols, 32);
  ASSERT_TRUE(r.rebuildSeconds.has_value());
  int tiles = 0, windows = 0;
  for (int y = 0; y < 32; y += 4)
    for (int x = 0; x < 32; x += 4, ++windows) tiles += isShiftedTile(r.image, exemplar, tile, x, y);
  EXPECT_EQ(tiles, windows);
}

// Averaged proposals blend the two colours at the discs' edges: the share of the disc colour is
// measured along the line between them.
TEST(SynthesizeTexture, TwoColorDiscFractionsMatchWithin5Percent) {
  const cv::Vec3f a{0.9f, 0.8f, 0.3f}, b{0.1f, 0.2f, 0.6f};
  const cv::Mat ex = test::randomDiscs(64, 0.3, 21, a, b);
  int discPixels = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) discPixels += ex.at<cv::Vec3f>(y, x) == b;
  for (TextureMethod m : {TextureMethod::Kwatra, TextureMethod::Skeletal}) {
    TextureSynthesisOptions o = smallOptions(m);
    o.width = o.height = 64;
    const TextureSynthesisResult r = synthesizeTexture(ex, o);
    double share = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) share += (a[0] - r.image.at<cv::Vec3f>(y, x)[0]) / (a[0] - b[0]);
    EXPECT_NEAR(share / (64 * 64), double(discPixels) / (64 * 64), 0.05) << textureMethodName(m);
  }
}

TEST(SynthesizeTexture, SameSeedSameImageWithOneAndTwoThreads) {
  const cv::Mat ex = test::smoothImage(40, 40);
  for (TextureMethod m : {TextureMethod::Kwatra, TextureMethod::Skeletal}) {
    TextureSynthesisOptions o = smallOptions(m);
    o.distance = m == TextureMethod::Skeletal ? NeighborhoodDistance::Wavelet : NeighborhoodDistance::Rgb;
    o.threads = 1;
    const cv::Mat one = synthesizeTexture(ex, o).image;
    o.threads = 2;
    const cv::Mat two = synthesizeTexture(ex, o).image;
    EXPECT_EQ(cv::norm(one, two, cv::NORM_INF), 0.0) << textureMethodName(m);
    o.seed = 2;
    EXPECT_GT(cv::norm(one, synthesizeTexture(ex, o).image, cv::NORM_INF), 0.0) << textureMethodName(m);
  }
}

TEST(SynthesizeTexture, BadInputIsOneLineInputError) {
  const cv::Mat ex = test::smoothImage(40, 40);
  TextureSynthesisOptions o = smallOptions(TextureMethod::Skeletal);
  o.neighborhoods = {24, 4};
  EXPECT_THROW(synthesizeTexture(ex, o), InputError);  // 20x20 at the coarse level < 24
  o = smallOptions(TextureMethod::Skeletal);
  o.width = 30;
  EXPECT_THROW(synthesizeTexture(ex, o), InputError);  // not a multiple of 2 x 2
  o.width = 32;
  o.waveletLevels = 2;
  EXPECT_THROW(synthesizeTexture(ex, o), InputError);  // nothing left to optimise
  EXPECT_THROW(parseTextureMethod("wavelet"), InputError);
  EXPECT_THROW(synthesizeTexture(cv::Mat(), smallOptions(TextureMethod::Kwatra)), InputError);
  try {
    o.waveletLevels = 1;
    o.height = 31;
    synthesizeTexture(ex, o);
    FAIL() << "an odd height was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}

// Without --neighborhoods, a 48x40 exemplar (12x10 at the coarsest of three levels) still runs: the
// default 16,12,8 shrink to half of each level's exemplar; asked for explicitly, 16 is refused.
TEST(SynthesizeTexture, DefaultNeighborhoodsFitSmallExemplars) {
  const cv::Mat ex = test::smoothImage(48, 40);
  TextureSynthesisOptions o;
  o.width = o.height = 32;
  o.iterations = 1;
  EXPECT_EQ(synthesizeTexture(ex, o).neighborhoods, (std::vector<int>{5, 10, 8}));
  o.neighborhoods = {16, 12, 8};
  EXPECT_THROW(synthesizeTexture(ex, o), InputError);
}
