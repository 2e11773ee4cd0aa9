#include <string>

#include <gtest/gtest.h>

#include "io/imageIO.h"
#include "segmentation/analyzeExemplar.h"
#include "segmentation/drawLabels.h"
#include "segmentation/reportJson.h"
#include "testHelpers.h"

namespace solidtex {
namespace {

ExemplarStats discs(cv::Mat& photo) {
  photo = test::discPhoto({200, 150}, {0.9f, 0.9f, 0.9f},
                          {{{50, 50}, 20, {0.2f, 0.3f, 0.8f}},
                           {{130, 80}, 25, {0.8f, 0.3f, 0.2f}},
                           {{3, 120}, 15, {0.1f, 0.6f, 0.1f}}});
  return analyzeExemplar(photo, "discs.png", {});
}

TEST(SegmentationReport, JsonHasTheDocumentedKeys) {
  cv::Mat photo;
  const ExemplarStats stats = discs(photo);
  const nlohmann::json j = toJson(stats);
  for (const char* key : {"particles", "area_fraction", "background_color", "histogram", "size_pairs",
                          "image", "particle_count", "min_area"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["particle_count"], stats.particles.size());
  EXPECT_EQ(j["image"]["name"], "discs.png");
  EXPECT_EQ(j["image"]["width"], 200);
  EXPECT_EQ(j["image"]["height"], 150);
  EXPECT_EQ(j["histogram"]["edges"].size(), 11u);
  EXPECT_EQ(j["histogram"]["counts"].size(), 10u);
  EXPECT_EQ(j["histogram"]["ratios"].size(), 10u);
  ASSERT_EQ(j["particles"].size(), stats.particles.size());
  const nlohmann::json& first = j["particles"][0];
  for (const char* key : {"id", "area", "width", "height", "x", "y", "color", "border"})
    EXPECT_TRUE(first.contains(key)) << key;
  EXPECT_EQ(first["id"], stats.particles[0].id);
  EXPECT_EQ(first["width"], stats.particles[0].box.width);
  EXPECT_EQ(first["color"].size(), 3u);
  EXPECT_EQ(j["background_color"].size(), 3u);
  EXPECT_EQ(j.dump().find("residual"), std::string::npos);
}

TEST(SegmentationReport, LabelsPictureIsEnlargedAndMarked) {
  cv::Mat photo;
  const ExemplarStats stats = discs(photo);
  const cv::Mat labels = drawLabels(photo, stats);
  ASSERT_EQ(labels.type(), CV_8UC3);
  EXPECT_GE(std::min(labels.cols, labels.rows), 512);
  EXPECT_EQ(labels.cols * photo.rows, labels.rows * photo.cols);  // a whole-number enlargement
  // The outlines are drawn in yellow (inner) and magenta (border) over the photo.
  cv::Mat yellow, magenta;
  cv::inRange(labels, cv::Scalar(200, 200, 0), cv::Scalar(255, 255, 60), yellow);
  cv::inRange(labels, cv::Scalar(200, 0, 200), cv::Scalar(255, 60, 255), magenta);
  EXPECT_GT(cv::countNonZero(yellow), 100);
  EXPECT_GT(cv::countNonZero(magenta), 20);
  writeImage((test::freshTempDir() / "labels.png").string(), labels);
}

TEST(SegmentationReport, LabelsOfATinyPhotoReachReadableSize) {
  const std::string path = test::dataPath("particles/leopard.png");
  const cv::Mat photo = loadPhoto(path);
  const cv::Mat labels = drawLabels(photo, analyzeExemplar(photo, "leopard.png", {}));
  EXPECT_GE(std::min(labels.cols, labels.rows), 512);
}

}  // namespace
}  // namespace solidtex
