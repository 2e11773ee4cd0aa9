#include <algorithm>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "segmentation/analyzeExemplar.h"
#include "segmentation/detail/morphology.h"

namespace solidtex {
namespace {

using segmentation::detail::crossMedian;
using segmentation::detail::restoreCorners;

cv::Mat squareImage() {
  cv::Mat image = cv::Mat::zeros(32, 32, CV_32FC1);
  image(cv::Rect(8, 8, 12, 12)).setTo(1.0f);
  return image;
}

TEST(CrossMedian, KeepsTheCornersOfASquareWhichTheSquareMedianRounds) {
  const cv::Mat square = squareImage();
  EXPECT_EQ(cv::countNonZero(crossMedian(square) != square), 0);
  cv::Mat squareMedian;
  cv::medianBlur(square, squareMedian, 3);
  EXPECT_EQ(cv::countNonZero(squareMedian != square), 4);  // the four corner pixels
}

TEST(CrossMedian, RemovesSpecksAndPairsButKeepsOnePixelLines) {
  cv::Mat image = cv::Mat::zeros(24, 24, CV_32FC1);
  image.at<float>(4, 4) = 1;
  image.at<float>(10, 4) = image.at<float>(10, 5) = 1;
  image.row(18).colRange(2, 22).setTo(1.0f);
  const cv::Mat filtered = crossMedian(image);
  EXPECT_EQ(filtered.at<float>(4, 4), 0);
  EXPECT_EQ(filtered.at<float>(10, 4), 0);
  EXPECT_EQ(filtered.at<float>(10, 5), 0);
  EXPECT_EQ(cv::countNonZero(filtered.row(18)), 18);  // the line less its two end pixels
}

// An L (the square less its top right quarter): five convex corners the square median clips
// and the concave one it fills.
TEST(RestoreCorners, PutsBackWhatTheSquareMedianMovedAtConvexAndConcaveCorners) {
  cv::Mat distance = squareImage();
  distance(cv::Rect(14, 8, 6, 6)).setTo(0.0f);
  cv::Mat rounded, mask;
  cv::medianBlur(distance, rounded, 3);
  mask = rounded > 0.5f;
  ASSERT_EQ(cv::countNonZero(mask != (distance > 0.5f)), 6);
  restoreCorners(mask, crossMedian(distance));
  EXPECT_EQ(cv::countNonZero(mask != (distance > 0.5f)), 0);
}

TEST(RestoreCorners, LeavesADiagonalStaircaseAsItsDistanceDrawsIt) {
  cv::Mat distance(32, 32, CV_32FC1);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) distance.at<float>(y, x) = x + y > 31 ? 1.0f : 0.0f;
  cv::Mat mask = distance > 0.5f;
  const cv::Mat staircase = mask.clone();
  restoreCorners(mask, crossMedian(distance));
  EXPECT_EQ(cv::countNonZero(mask != staircase), 0);
}

TEST(RestoreCorners, MovesNothingAgainstAFlatOrReversedDistance) {
  cv::Mat mask = cv::Mat::zeros(32, 32, CV_8UC1);
  mask(cv::Rect(8, 8, 12, 12)).setTo(255);
  const cv::Mat drawn = mask.clone();
  restoreCorners(mask, cv::Mat(32, 32, CV_32FC1, cv::Scalar(7.0f)));
  EXPECT_EQ(cv::countNonZero(mask != drawn), 0);
  // Further from the background outside than inside, and the square's corners read as outside:
  // against a reversed step they would be taken out.
  cv::Mat reversed = 1 - squareImage();
  for (const cv::Point corner : {cv::Point(8, 8), cv::Point(19, 8), cv::Point(8, 19), cv::Point(19, 19)})
    reversed.at<float>(corner) = 1;
  restoreCorners(mask, reversed);
  EXPECT_EQ(cv::countNonZero(mask != drawn), 0);
}

// Axis-aligned squares and rectangles with the truth photos' colours and noise: every pixel of
// every particle is found, corners included (the square median lost four per particle).
TEST(AngularOutlines, SquaresKeepEveryCornerPixel) {
  cv::Mat photo(200, 200, CV_32FC3, cv::Scalar(0.16, 0.16, 0.17));
  std::vector<cv::Rect> boxes;
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col)
      boxes.emplace_back(12 + 46 * col, 12 + 46 * row, 14 + 4 * col, 14 + 4 * row);
  for (const cv::Rect& box : boxes) photo(box).setTo(cv::Scalar(0.92, 0.55, 0.16));
  cv::Mat grain(photo.size(), CV_32FC3);
  cv::RNG rng(3);
  rng.fill(grain, cv::RNG::NORMAL, 0.0, 0.02);
  cv::min(cv::max(photo + grain, 0.0), 1.0, photo);

  const ExemplarStats stats = analyzeExemplar(photo, "squares", {});
  EXPECT_FALSE(stats.halfMaximumOutlines);
  ASSERT_EQ(stats.particles.size(), boxes.size());
  const auto byPlace = [](const cv::Rect& a, const cv::Rect& b) {
    return std::tie(a.y, a.x) < std::tie(b.y, b.x);
  };
  std::vector<cv::Rect> foundBoxes;
  for (const Particle2D& p : stats.particles) foundBoxes.push_back(p.box);
  std::sort(foundBoxes.begin(), foundBoxes.end(), byPlace);
  std::sort(boxes.begin(), boxes.end(), byPlace);
  EXPECT_EQ(foundBoxes, boxes);
  for (const Particle2D& p : stats.particles) {
    EXPECT_EQ(p.area, double(p.box.area())) << "particle " << p.id;
    EXPECT_EQ(cv::countNonZero(p.mask), p.box.area()) << "particle " << p.id;
  }
}

}  // namespace
}  // namespace solidtex
