#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <Eigen/Geometry>

#include "common/Random.h"
#include "validation/orientationAgreement.h"

namespace solidtex {
namespace {

constexpr int kSide = 40;
constexpr double kPeriod = 8;

template <typename Value>
DenseVolume volumeOf(int side, Value value) {
  DenseVolume v;
  v.dims = {side, side, side};
  v.values.resize(v.dims.count());
  for (int k = 0; k < side; ++k)
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) v.values[v.dims.index(i, j, k)] = float(value(i, j, k));
  return v;
}

// Planar bands sin(2 pi n.x / 8).
DenseVolume bands(const Eigen::Vector3d& normal) {
  const Eigen::Vector3d n = normal.normalized();
  return volumeOf(kSide, [&](int i, int j, int k) {
    return std::sin(2 * std::numbers::pi * n.dot(Eigen::Vector3d(i, j, k)) / kPeriod);
  });
}

constexpr double kCentre = (kSide - 1) / 2.0;

Eigen::Vector3f radial(int i, int j, int) { return {float(i - kCentre), float(j - kCentre), 0.f}; }

// Concentric cylinders around the z axis through the centre: rings in every XY slice.
DenseVolume cylinders() {
  return volumeOf(kSide, [](int i, int j, int) {
    return std::sin(2 * std::numbers::pi * std::hypot(i - kCentre, j - kCentre) / kPeriod);
  });
}

DenseVolume noise(std::uint64_t seed) {
  Rng rng(seed);
  return volumeOf(kSide, [&](int, int, int) { return uniform01(rng); });
}

auto constant(const Eigen::Vector3d& d) {
  const Eigen::Vector3f f = d.cast<float>();
  return [f](int, int, int) { return f; };
}

TEST(OrientationAgreement, AxisAlignedBandsFollowTheirNormal) {
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d n = Eigen::Vector3d::Unit(axis), across = Eigen::Vector3d::Unit((axis + 1) % 3);
    const DenseVolume v = bands(n);
    const auto along = orientationAgreement(v, constant(n));
    EXPECT_GT(along.meanAbsCos, 0.95) << axis;
    EXPECT_EQ(along.voxelsTotal, std::size_t(28 * 28 * 28));  // the default margin is 6
    EXPECT_GT(along.voxelsCounted, along.voxelsTotal * 9 / 10) << axis;
    EXPECT_LT(orientationAgreement(v, constant(across)).meanAbsCos, 0.1) << axis;
  }
}

TEST(OrientationAgreement, ObliqueBandsFollowTheirNormal) {
  for (const Eigen::Vector3d& n :
       {Eigen::Vector3d(1, 2, 2), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(-3, 1, 2)}) {
    const DenseVolume v = bands(n);
    const auto along = orientationAgreement(v, constant(n));
    EXPECT_GT(along.meanAbsCos, 0.95) << n.transpose();
    EXPECT_GT(along.voxelsCounted, along.voxelsTotal * 9 / 10) << n.transpose();
    const Eigen::Vector3d perpendicular = n.cross(Eigen::Vector3d(0, 0, 1)).normalized();
    EXPECT_LT(orientationAgreement(v, constant(perpendicular)).meanAbsCos, 0.1) << n.transpose();
    EXPECT_LT(orientationAgreement(v, constant(n.cross(perpendicular))).meanAbsCos, 0.1) << n.transpose();
  }
}

TEST(OrientationAgreement, CylindersAreRadial) {
  const DenseVolume v = cylinders();
  const auto r = orientationAgreement(v, radial);
  EXPECT_GT(r.meanAbsCos, 0.9);
  EXPECT_GT(r.voxelsCounted, r.voxelsTotal / 2);
  // The tangential direction, and z, are across the gradient.
  EXPECT_LT(orientationAgreement(v,
                                 [](int i, int j, int k) {
                                   const Eigen::Vector3f d = radial(i, j, k);
                                   return Eigen::Vector3f(-d.y(), d.x(), 0.f);
                                 })
                .meanAbsCos,
            0.2);
  EXPECT_LT(orientationAgreement(v, constant({0, 0, 1})).meanAbsCos, 0.1);
}

TEST(OrientationAgreement, NoiseHasNoClearOrientation) {
  const auto r = orientationAgreement(noise(7), constant({1, 0, 0}));
  EXPECT_EQ(r.voxelsTotal, std::size_t(28 * 28 * 28));
  EXPECT_LT(r.voxelsCounted, r.voxelsTotal / 10);
}

TEST(OrientationAgreement, ColourChannelsSumTheirTensors) {
  const DenseVolume gray = bands({1, 2, 2});
  DenseVolume rgb;
  rgb.dims = gray.dims;
  rgb.channels = 3;
  rgb.values.resize(gray.values.size() * 3);
  for (std::size_t v = 0; v < gray.values.size(); ++v) {
    rgb.values[3 * v] = 0.5f + 0.5f * gray.values[v];
    rgb.values[3 * v + 1] = 0.5f - 0.3f * gray.values[v];  // anti-correlated: luminance would cancel some
    rgb.values[3 * v + 2] = 0.25f;
  }
  EXPECT_GT(orientationAgreement(rgb, constant({1, 2, 2})).meanAbsCos, 0.95);
}

TEST(OrientationAgreement, FlatVolumeCountsNothing) {
  const auto r = orientationAgreement(volumeOf(20, [](int, int, int) { return 0.3; }), constant({1, 0, 0}));
  EXPECT_EQ(r.voxelsCounted, 0u);
  EXPECT_EQ(r.meanAbsCos, 0);
  EXPECT_GT(r.voxelsTotal, 0u);
  // Too small for the margin.
  EXPECT_EQ(
      orientationAgreement(volumeOf(12, [](int, int, int) { return 0.3; }), constant({1, 0, 0})).voxelsTotal,
      0u);
}

TEST(OrientationAgreement, SameAnswerWithOneAndTwoThreads) {
  DenseVolume v = cylinders();
  const DenseVolume n = noise(11);
  for (std::size_t i = 0; i < v.values.size(); ++i) v.values[i] += 0.5f * n.values[i];
  OrientationAgreement one, two;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = orientationAgreement(v, radial);
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    two = orientationAgreement(v, radial);
  }
  EXPECT_EQ(one.meanAbsCos, two.meanAbsCos);
  EXPECT_EQ(one.voxelsCounted, two.voxelsCounted);
  EXPECT_EQ(one.voxelsTotal, two.voxelsTotal);
  EXPECT_GT(one.voxelsCounted, 0u);
}

TEST(OrientationAgreement, RejectsMismatchedVolumes) {
  DenseVolume v = volumeOf(16, [](int, int, int) { return 0.0; });
  v.values.pop_back();
  EXPECT_THROW(orientationAgreement(v, constant({1, 0, 0})), std::invalid_argument);
  OrientationOptions negative;
  negative.tensorSigma = -1;
  EXPECT_THROW(
      orientationAgreement(volumeOf(16, [](int, int, int) { return 0.0; }), constant({1, 0, 0}), negative),
      std::invalid_argument);
}

}  // namespace
}  // namespace solidtex
