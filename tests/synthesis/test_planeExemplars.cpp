#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "TestImages.h"
#include "common/Error.h"
#include "common/srgb.h"
#include "synthesis/synthesizeSolid.h"
#include "validation/continuousQuality.h"

using namespace solidtex;

namespace {

/// The bundled bedded stone's yz, xz and xy sections (data/continuous/planes): horizontal wavy beds
/// on the planes through z, a mottled bedding plane on xy.
std::array<cv::Mat, 3> beddedPlanes() {
  std::array<cv::Mat, 3> planes;
  const char* names[3] = {"yz", "xz", "xy"};
  for (int axis = 0; axis < 3; ++axis) {
    cv::Mat bgr =
        cv::imread(std::string(SOLIDTEX_DATA_DIR) + "/continuous/planes/bedded_" + names[axis] + ".png");
    cv::cvtColor(bgr, planes[axis], cv::COLOR_BGR2RGB);
    planes[axis].convertTo(planes[axis], CV_32FC3, 1.0 / 255);
  }
  return planes;
}

SynthesisOptions planeOptions(Method method) {
  SynthesisOptions o;
  o.method = method;
  o.size = 32;
  o.levels = 2;
  o.neighborhoods = {8, 4};
  o.iterations = 3;
  if (method == Method::Skeletal) o.levels = 3, o.neighborhoods = {6, 4, 4};
  return o;
}

/// Mean absolute sRGB difference between neighbouring voxels along `along` (periodic volume).
double meanStep(const SolidVolume& v, int along) {
  double sum = 0;
  const int n = v.dims.x;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        int at[3] = {x, y, z};
        at[along] = (at[along] + 1) % n;
        const auto& a = v.color[v.dims.index(x, y, z)];
        const auto& b = v.color[v.dims.index(at[0], at[1], at[2])];
        for (int c = 0; c < 3; ++c) sum += std::abs(linearToSrgb(a[c]) - linearToSrgb(b[c]));
      }
  return sum / double(v.dims.count());
}

ContinuousQualityOptions fewPatches(int planeAxis) {
  ContinuousQualityOptions q;
  q.planeAxis = planeAxis;
  q.patches = 1024;
  q.queries = 256;
  return q;
}

/// The bidirectional similarity of the slices orthogonal to `axis` (every axis: -1) to `exemplar`.
double planeSimilarity(const SolidVolume& v, const cv::Mat& exemplar, int axis) {
  return measureContinuousSolid(v, exemplar, {}, fewPatches(axis)).axis.bidirectional();
}

}  // namespace

TEST(PlaneExemplars, ThreeEqualExemplarsGiveTheOneExemplarVolume) {
  const cv::Mat ex = test::smoothImage(40, 40);
  SynthesisOptions o = planeOptions(Method::ChenWang);
  o.size = 16;
  o.neighborhoods = {6, 4};
  const SynthesisResult one = synthesizeSolid(ex, o);
  const SynthesisResult three = synthesizeSolid(std::array<cv::Mat, 3>{ex.clone(), ex.clone(), ex}, o);
  EXPECT_EQ(one.volume.color, three.volume.color);
  EXPECT_EQ(one.volume.sourcePosition, three.volume.sourcePosition);
}

// Bedded stone from its three planes: the colour changes more often down the beds (z) than along
// them; each plane's slices are as near their own photo as a solid from that photo alone, and about
// as far from the other kind of plane's photo as their own photo is (the x slices, beds, from the
// mottled xy photo; the z slices, mottled, from the beds of the xz photo). From the xy photo alone
// every direction looks alike.
TEST(PlaneExemplars, BedsLieAcrossZWithEachMethod) {
  const std::array<cv::Mat, 3> planes = beddedPlanes();
  constexpr std::pair<int, int> kAxisAndWrongPlane[2] = {{0, 2}, {2, 1}};
  // The photo itself against the wrong plane's photo: what slices exactly like it would score.
  double photoWrong[3] = {};
  for (const auto& [axis, other] : kAxisAndWrongPlane)
    photoWrong[axis] =
        measureTexture(planes[axis], planes[other], {}, fewPatches(-1)).texture.bidirectional();
  for (Method m : {Method::ChenWang, Method::Kopf, Method::Skeletal}) {
    SCOPED_TRACE(methodName(m));
    const SolidVolume beds = synthesizeSolid(planes, planeOptions(m)).volume;
    const double sx = meanStep(beds, 0), sy = meanStep(beds, 1), sz = meanStep(beds, 2);
    EXPECT_GT(sz, 1.3 * std::max(sx, sy)) << sx << " " << sy << " " << sz;
    for (const auto& [axis, other] : kAxisAndWrongPlane) {
      const double own = planeSimilarity(beds, planes[axis], axis);
      const double wrong = planeSimilarity(beds, planes[other], axis);
      EXPECT_LT(own, wrong) << "axis " << axis;
      EXPECT_GT(wrong, 0.8 * photoWrong[axis])
          << "axis " << axis << ": " << own << " " << wrong << " " << photoWrong[axis];
      const SolidVolume alone = synthesizeSolid(planes[axis], planeOptions(m)).volume;
      EXPECT_LT(own, 1.25 * planeSimilarity(alone, planes[axis], -1)) << "axis " << axis;
      if (axis == 2) {
        EXPECT_LT(meanStep(alone, 2), 1.25 * meanStep(alone, 0));
      }
    }
  }
}

TEST(PlaneExemplars, SameSeedSameOutputWithOneAndTwoThreads) {
  std::array<cv::Mat, 3> planes = beddedPlanes();
  for (cv::Mat& plane : planes) plane = plane(cv::Rect(0, 0, 48, 48)).clone();
  for (Method m : {Method::ChenWang, Method::Kopf}) {
    SynthesisOptions o = planeOptions(m);
    o.size = 16;
    o.neighborhoods = {6, 4};
    o.iterations = 2;
    o.threads = 1;
    const SynthesisResult one = synthesizeSolid(planes, o);
    o.threads = 2;
    const SynthesisResult two = synthesizeSolid(planes, o);
    EXPECT_EQ(one.volume.color, two.volume.color) << methodName(m);
    EXPECT_TRUE(two.volume.sourcePosition.empty());
  }
}

TEST(PlaneExemplars, BadInputThrows) {
  const cv::Mat ex = test::smoothImage(40, 40), wide = test::smoothImage(48, 40);
  SynthesisOptions o = planeOptions(Method::ChenWang);
  EXPECT_THROW(synthesizeSolid(std::array<cv::Mat, 3>{ex, wide, ex}, o), InputError);
  EXPECT_THROW(synthesizeSolid(std::array<cv::Mat, 3>{ex, test::smoothImage(6, 6), ex}, o), InputError);
  o.control = cv::Mat(40, 40, CV_32FC1, cv::Scalar(0.5));
  EXPECT_THROW(synthesizeSolid(std::array<cv::Mat, 3>{ex, test::randomImage(40, 40, 1), ex}, o), OptionError);
}
