#include <gtest/gtest.h>

#include <filesystem>

#include <OpenImageIO/imageio.h>

#include "common/Error.h"
#include "io/imageIO.h"
#include "pipeline/planePixelSizes.h"

namespace solidtex {
namespace {

namespace fs = std::filesystem;

// A grey 40 x 30 TIFF, with a resolution in pixels per centimetre when `perCm` is positive.
std::string tiff(const std::string& name, float perCm) {
  const fs::path path = fs::temp_directory_path() / ("solidtex_pixel_sizes_" + name + ".tif");
  OIIO::ImageSpec spec(40, 30, 3, OIIO::TypeDesc::UINT8);
  if (perCm > 0) {
    spec.attribute("XResolution", perCm);
    spec.attribute("YResolution", perCm);
    spec.attribute("ResolutionUnit", "cm");
  }
  const std::vector<unsigned char> pixels(40 * 30 * 3, 128);
  auto out = OIIO::ImageOutput::create(path.string());
  EXPECT_TRUE(out && out->open(path.string(), spec) &&
              out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) && out->close());
  return path.string();
}

TEST(PlanePixelSizes, TheFilesResolutionsGiveThePixelSizes) {
  const std::string xy = tiff("xy", 1000), xz = tiff("xz", 500), bare = tiff("bare", 0);
  const auto sizes = planePixelSizes({}, {xy, xz, xz}, true);
  ASSERT_TRUE(sizes.has_value());
  EXPECT_NEAR((*sizes)[0][0], 1e-5, 1e-9);  // 1000 pixels a centimetre: 10 micrometres
  EXPECT_NEAR((*sizes)[1][1], 2e-5, 1e-9);
  EXPECT_FALSE(planePixelSizes({}, {xy, xz, xz}, false).has_value());  // only when asked
  EXPECT_THROW(planePixelSizes({}, {bare, bare, bare}, true), InputError);
  // Some files say and one does not: which scale it has cannot be known.
  try {
    planePixelSizes({}, {xy, xz, bare}, true);
    ADD_FAILURE() << "a file without a pixel size was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(bare), std::string::npos) << e.what();
  }
  // Given sizes win over the files'.
  EXPECT_EQ((*planePixelSizes({1, 2, 3}, {bare, bare, bare}, true))[2], (PixelSize{3, 3}));
  EXPECT_THROW(planePixelSizes({1, 0, 1}, {bare, bare, bare}, false), OptionError);
  EXPECT_THROW(planePixelSizes({1, 2}, {bare, bare, bare}, false), OptionError);
}

TEST(PlanePixelSizes, PhotosAreResampledToTheXyPhotosPixelsWithinAReconcilableRatio) {
  const cv::Mat photo(30, 40, CV_32FC3, cv::Scalar(0.2, 0.4, 0.6));
  const cv::Mat twice = atPixelSize(photo, {2, 2}, 1, "xz.png");
  EXPECT_EQ(twice.size(), cv::Size(80, 60));
  EXPECT_NEAR(cv::mean(twice)[1], 0.4, 1e-6);
  EXPECT_EQ(atPixelSize(photo, {1, 1}, 1, "xz.png").data, photo.data);
  EXPECT_EQ(atPixelSize(photo, {1, 0.5}, 1, "xz.png").size(), cv::Size(40, 15));
  EXPECT_THROW(atPixelSize(photo, {10, 10}, 1, "xz.png"), InputError);
  EXPECT_THROW(atPixelSize(photo, {0.2, 0.2}, 1, "xz.png"), InputError);  // 8 x 6: smaller than a photo
  EXPECT_THROW(squarePixelSide({1, 1.2}, "xy.png"), InputError);
  EXPECT_EQ(squarePixelSide({1, 1.005}, "xy.png"), 1);
}

}  // namespace
}  // namespace solidtex
