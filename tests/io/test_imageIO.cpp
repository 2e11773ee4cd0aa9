#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <vector>

#include <unistd.h>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "common/Error.h"
#include "common/memoryBudget.h"
#include "io/detail/CapturedStderr.h"
#include "io/imageIO.h"
#include "testHelpers.h"

namespace solidtex {
namespace {

namespace fs = std::filesystem;
using test::freshTempDir;

// The error must be one line that names the file.
void expectInputError(const std::string& path, const std::string& fragment) {
  try {
    loadPhoto(path);
    FAIL() << "no InputError for " << path;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(fs::path(path).filename().string()), std::string::npos) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

template <typename T>
void writeWithOiio(const fs::path& path, int width, int height, int channels, OIIO::TypeDesc type,
                   const std::vector<T>& pixels) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(width, height, channels, type);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // store the colour as given, not divided by alpha
  ASSERT_TRUE(out->open(path.string(), spec));
  ASSERT_TRUE(out->write_image(type, pixels.data()));
  ASSERT_TRUE(out->close());
}

TEST(ImageIO, RoundTripsAnRgbImage) {
  const fs::path path = freshTempDir() / "rgb.png";
  cv::Mat rgb(10, 12, CV_8UC3);
  for (int y = 0; y < rgb.rows; ++y)
    for (int x = 0; x < rgb.cols; ++x)
      rgb.at<cv::Vec3b>(y, x) = {uchar(20 * x), uchar(25 * y), uchar(7 * (x + y))};
  writeImage(path.string(), rgb);
  const cv::Mat loaded = loadPhoto(path.string());
  ASSERT_EQ(loaded.type(), CV_32FC3);
  ASSERT_EQ(loaded.size(), rgb.size());
  for (int y = 0; y < rgb.rows; ++y)
    for (int x = 0; x < rgb.cols; ++x)
      for (int c = 0; c < 3; ++c)
        EXPECT_FLOAT_EQ(loaded.at<cv::Vec3f>(y, x)[c], rgb.at<cv::Vec3b>(y, x)[c] / 255.0f);
}

TEST(ImageIO, WritesFloatImagesRoundedToEightBits) {
  const fs::path path = freshTempDir() / "float.png";
  const cv::Mat srgb(9, 9, CV_32FC3, cv::Scalar(0.1, 0.5, 0.9));
  writeImage(path.string(), srgb);
  const cv::Mat loaded = loadPhoto(path.string());
  EXPECT_LE(cv::norm(loaded, srgb, cv::NORM_INF), 0.5 / 255.0 + 1e-6);
}

TEST(ImageIO, LeavesNoTemporaryFileBehind) {
  const fs::path dir = freshTempDir();
  writeImage((dir / "a.png").string(), cv::Mat(8, 8, CV_8UC3, cv::Scalar(1, 2, 3)));
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) files.push_back(entry.path().filename());
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0], "a.png");
}

TEST(ImageIO, RefusesAnUnwritablePath) {
  const fs::path dir = freshTempDir();
  EXPECT_THROW(writeImage((dir / "missing" / "a.png").string(), cv::Mat(8, 8, CV_8UC3, cv::Scalar(0))),
               InputError);
  EXPECT_THROW(writeImage((dir / "b.png").string(), cv::Mat(8, 8, CV_16UC3, cv::Scalar(0))), InputError);
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(ImageIO, GreyBecomesEqualChannels) {
  const fs::path path = freshTempDir() / "grey.png";
  writeImage(path.string(), cv::Mat(8, 10, CV_8UC1, cv::Scalar(128)));
  const cv::Mat loaded = loadPhoto(path.string());
  ASSERT_EQ(loaded.type(), CV_32FC3);
  EXPECT_EQ(loaded.at<cv::Vec3f>(3, 4), cv::Vec3f(128 / 255.0f, 128 / 255.0f, 128 / 255.0f));
}

TEST(ImageIO, ReadsSixteenBitAndDropsAlpha) {
  const fs::path path = freshTempDir() / "rgba16.png";
  std::vector<std::uint16_t> pixels(8 * 8 * 4);
  for (std::size_t i = 0; i < pixels.size(); i += 4) {
    pixels[i] = 65535;
    pixels[i + 1] = 32768;
    pixels[i + 2] = 0;
    pixels[i + 3] = 1000;  // alpha: must not leak into the colour
  }
  writeWithOiio(path, 8, 8, 4, OIIO::TypeDesc::UINT16, pixels);
  const cv::Mat loaded = loadPhoto(path.string());
  ASSERT_EQ(loaded.type(), CV_32FC3);
  const cv::Vec3f p = loaded.at<cv::Vec3f>(5, 5);
  EXPECT_FLOAT_EQ(p[0], 1.0f);
  EXPECT_NEAR(p[1], 32768 / 65535.0f, 1e-6f);
  EXPECT_FLOAT_EQ(p[2], 0.0f);
}

TEST(ImageIO, EncodesLinearFloatImagesToSrgb) {
  const fs::path path = freshTempDir() / "linear.exr";
  std::vector<float> pixels(8 * 8 * 3, 0.18f);
  writeWithOiio(path, 8, 8, 3, OIIO::TypeDesc::FLOAT, pixels);
  const cv::Mat loaded = loadPhoto(path.string());
  EXPECT_NEAR(loaded.at<cv::Vec3f>(2, 2)[1], 0.461356f, 1e-4f);
}

TEST(ImageIO, MissingFileIsAnInputError) {
  expectInputError((freshTempDir() / "nowhere.png").string(), "not found");
}

TEST(ImageIO, NonImageFileIsAnInputError) {
  const fs::path path = freshTempDir() / "notes.png";
  test::writeBytes(path, {'h', 'e', 'l', 'l', 'o', '\n'});
  expectInputError(path.string(), "not an image");
}

TEST(ImageIO, TruncatedPngIsAnInputError) {
  const fs::path dir = freshTempDir();
  const fs::path whole = dir / "whole.png";
  cv::Mat noise(64, 64, CV_8UC3);
  cv::RNG(7).fill(noise, cv::RNG::UNIFORM, 0,
                  256);  // incompressible, so half the file really misses pixel data
  writeImage(whole.string(), noise);
  std::vector<unsigned char> bytes = test::readBytes(whole);
  bytes.resize(bytes.size() / 2);
  const fs::path cut = dir / "cut.png";
  test::writeBytes(cut, bytes);
  expectInputError(cut.string(), "truncated");
}

TEST(ImageIO, OnePixelImageIsAnInputError) {
  const fs::path path = freshTempDir() / "dot.png";
  writeImage(path.string(), cv::Mat(1, 1, CV_8UC3, cv::Scalar(9, 9, 9)));
  expectInputError(path.string(), "too small");
}

TEST(ImageIO, HugeHeaderIsRefusedBeforeDecoding) {
  const fs::path path = freshTempDir() / "huge.png";
  test::writeBytes(path, test::pngHeaderClaiming(30000, 30000));
  expectInputError(path.string(), "30000x30000");
}

TEST(ImageIO, HeaderNeedingMoreMemoryThanAvailableIsRefused) {
  const fs::path path = freshTempDir() / "large.png";
  test::writeBytes(path, test::pngHeaderClaiming(20000, 20000));  // within the side limit
  setMemoryLimit(std::uint64_t(1) << 30);
  expectInputError(path.string(), "20000x20000");
  expectInputError(path.string(), "memory");
  setMemoryLimit(0);
}

TEST(ImageIO, ReadsInStripsAcrossWideRows) {
  // 6000 RGB floats a row: a strip (1 MiB of floats) holds 14 rows, so this image takes several.
  const fs::path path = freshTempDir() / "wide.png";
  cv::Mat pattern(100, 6000, CV_8UC3);
  for (int y = 0; y < pattern.rows; ++y)
    for (int x = 0; x < pattern.cols; ++x)
      pattern.at<cv::Vec3b>(y, x) = {uchar(x), uchar(y * 3), uchar(x / 256)};
  writeImage(path.string(), pattern);
  cv::Mat expected;
  pattern.convertTo(expected, CV_32FC3, 1 / 255.0);
  EXPECT_EQ(cv::norm(loadPhoto(path.string()), expected, cv::NORM_INF), 0);
}

TEST(ImageIO, ReadsTiledImages) {
  const fs::path path = freshTempDir() / "tiled.tif";
  const int width = 40, height = 37;
  std::vector<std::uint8_t> pixels(std::size_t(width) * height * 3);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = std::uint8_t(i * 7);
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  spec.tile_width = spec.tile_height = 16;
  ASSERT_TRUE(out->open(path.string(), spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
  ASSERT_TRUE(out->close());
  const cv::Mat loaded = loadPhoto(path.string());
  ASSERT_EQ(loaded.size(), cv::Size(width, height));
  for (int y : {0, 15, 16, 36})
    for (int x : {0, 17, 39})
      for (int c = 0; c < 3; ++c)
        EXPECT_FLOAT_EQ(loaded.at<cv::Vec3f>(y, x)[c], pixels[(std::size_t(y) * width + x) * 3 + c] / 255.0f);
}

TEST(ImageIO, CorruptPngIsAnInputErrorAndPrintsNothing) {
  const fs::path dir = freshTempDir();
  const fs::path whole = dir / "whole.png";
  cv::Mat noise(64, 64, CV_8UC3);
  cv::RNG(7).fill(noise, cv::RNG::UNIFORM, 0, 256);
  writeImage(whole.string(), noise);
  std::vector<unsigned char> bytes = test::readBytes(whole);
  // Flip bytes in the middle of the pixel data (noise does not compress: it fills the file):
  // libpng rejects the chunk and prints "libpng error: IDAT: CRC error" itself.
  for (std::size_t i = bytes.size() / 2; i < bytes.size() / 2 + 16; ++i) bytes[i] ^= 0x5a;
  const fs::path corrupt = dir / "corrupt.png";
  test::writeBytes(corrupt, bytes);
  testing::internal::CaptureStderr();
  EXPECT_THROW(loadPhoto(corrupt.string()), InputError);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  expectInputError(corrupt.string(), "corrupt");
}

TEST(ImageIO, CapturedStderrTakesWhatLibrariesPrint) {
  testing::internal::CaptureStderr();
  std::string captured;
  {
    io::detail::CapturedStderr capture;
    std::fprintf(stderr, "libfoo error: first line\n\n");
    const char raw[] = "  second line  \n";
    ASSERT_EQ(::write(STDERR_FILENO, raw, sizeof raw - 1), ssize_t(sizeof raw - 1));
    captured = capture.finish();
    std::fprintf(stderr, "after");  // stderr is back
  }
  EXPECT_EQ(captured, "libfoo error: first line; second line");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "after");
}

TEST(ImageIO, CapturedStderrNests) {
  testing::internal::CaptureStderr();
  std::string outer, inner;
  {
    io::detail::CapturedStderr a;
    std::fprintf(stderr, "outer\n");
    {
      io::detail::CapturedStderr b;
      std::fprintf(stderr, "inner\n");
      inner = b.finish();
    }
    std::fprintf(stderr, "outer again\n");
    outer = a.finish();
  }
  EXPECT_EQ(inner, "inner");
  EXPECT_EQ(outer, "outer; outer again");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(ImageIO, ReadsTheExemplars) {
  const cv::Mat leopard = loadPhoto(test::dataPath("particles/leopard.png"));
  EXPECT_EQ(leopard.size(), cv::Size(64, 62));
  const cv::Mat gravel = loadPhoto(test::dataPath("particles/gravel.png"));
  EXPECT_EQ(gravel.size(), cv::Size(512, 512));
}

}  // namespace
}  // namespace solidtex
