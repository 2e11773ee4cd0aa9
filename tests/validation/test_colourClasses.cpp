#include <gtest/gtest.h>

#include "common/Error.h"
#include "common/srgb.h"
#include "validation/colourClasses.h"

namespace solidtex {
namespace {

// Three colour blocks with a little noise: k-means finds them, darkest first, and the solid's
// voxels of the same colours (linear RGB) fall in the same classes.
TEST(ColourClasses, FindsTheColoursOfAPhotoAndClassifiesVoxelsAlike) {
  const cv::Vec3f colours[3] = {{0.8f, 0.75f, 0.7f}, {0.1f, 0.1f, 0.12f}, {0.7f, 0.2f, 0.15f}};
  cv::Mat photo(60, 90, CV_32FC3);
  cv::RNG noise(3);
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 90; ++x) {
      const cv::Vec3f c = colours[x / 30];
      photo.at<cv::Vec3f>(y, x) =
          c + cv::Vec3f(float(noise.gaussian(0.01)), float(noise.gaussian(0.01)), 0.0f);
    }
  const ColourClasses classes = colourClasses(photo, 3, 7);
  ASSERT_EQ(classes.centres.rows, 3);
  EXPECT_LT(classes.centres.at<float>(0, 0), classes.centres.at<float>(1, 0));
  EXPECT_LT(classes.centres.at<float>(1, 0), classes.centres.at<float>(2, 0));
  const int expected[3] = {2, 0, 1};  // the blocks' classes by lightness: light, dark, red
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 90; ++x)
      ASSERT_EQ(classes.labels.at<std::int32_t>(y, x), expected[x / 30]) << x << ' ' << y;
  std::vector<Rgb> voxels;
  for (const cv::Vec3f& c : colours)
    voxels.push_back({srgbToLinear(c[0]), srgbToLinear(c[1]), srgbToLinear(c[2])});
  EXPECT_EQ(nearestClasses(voxels, classes.centres), (std::vector<std::uint8_t>{2, 0, 1}));
  EXPECT_EQ(colourClasses(photo, 3, 7).labels.at<std::int32_t>(0, 0), classes.labels.at<std::int32_t>(0, 0));
}

TEST(ColourClasses, RefusesOneClassOrMoreThanEight) {
  const cv::Mat photo(8, 8, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  EXPECT_THROW(colourClasses(photo, 1, 1), OptionError);
  EXPECT_THROW(colourClasses(photo, 9, 1), OptionError);
}

// A label image's values, not the photo's colours, decide the classes: a red and a grey half under
// labels 0.6 (left) and 0.2 (right) are classes 1 and 0; each centre is its half's colour.
TEST(ColourClasses, OfALabelImageFollowTheLabelsInTheirOrder) {
  cv::Mat photo(20, 40, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5)), labels(20, 40, CV_32FC3, cv::Scalar::all(0.2));
  photo.colRange(0, 20).setTo(cv::Scalar(0.8, 0.1, 0.1));
  labels.colRange(0, 20).setTo(cv::Scalar::all(0.6));
  const ColourClasses classes = colourClassesOfLabels(photo, labels, "labels");
  ASSERT_EQ(classes.centres.rows, 2);
  EXPECT_EQ(classes.labels.at<std::int32_t>(5, 3), 1);
  EXPECT_EQ(classes.labels.at<std::int32_t>(5, 30), 0);
  const Rgb grey{srgbToLinear(0.5f), srgbToLinear(0.5f), srgbToLinear(0.5f)};
  const Rgb red{srgbToLinear(0.8f), srgbToLinear(0.1f), srgbToLinear(0.1f)};
  EXPECT_EQ(nearestClasses({grey, red}, classes.centres), (std::vector<std::uint8_t>{0, 1}));
  EXPECT_NEAR(classes.centres.at<float>(0, 1), 0.0f, 1e-3f);  // grey: a* = 0
  EXPECT_GT(classes.centres.at<float>(1, 1), 40.0f);          // red: a* well above 0

  EXPECT_THROW(colourClassesOfLabels(photo, cv::Mat(20, 40, CV_32FC3, cv::Scalar::all(0.2)), "one"),
               InputError);
  EXPECT_THROW(colourClassesOfLabels(photo, labels.rowRange(0, 10).clone(), "small"), InputError);
  cv::Mat nine(20, 40, CV_32FC3);
  for (int x = 0; x < 40; ++x) nine.col(x).setTo(cv::Scalar::all((x % 9) / 8.0));
  EXPECT_THROW(colourClassesOfLabels(photo, nine, "nine"), InputError);
}

}  // namespace
}  // namespace solidtex
