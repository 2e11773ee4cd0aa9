#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "common/Error.h"
#include "io/frameFieldIO.h"
#include "io/vdbIO.h"
#include "synthesis/FrameField.h"
#include "tests/scratchPath.h"

using namespace solidtex;

namespace {

const Dims kDims{24, 20, 6};

Eigen::Vector3f column(const FrameField& f, int i, int j, int k, int axis) { return f.at(i, j, k).col(axis); }

// Replaces every occurrence of `from` by `to` (same length) in the file's bytes.
void patchBytes(const std::string& path, const std::string& from, const std::string& to) {
  ASSERT_EQ(from.size(), to.size());
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::size_t found = 0;
  for (auto at = bytes.find(from); at != std::string::npos; at = bytes.find(from, at + 1), ++found)
    bytes.replace(at, from.size(), to);
  ASSERT_GT(found, 0u);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace

TEST(FrameField, BuiltinFramesAreRotations) {
  ASSERT_EQ(builtinFrameFieldNames().size(), 5u);
  for (const auto& name : builtinFrameFieldNames()) {
    const FrameField f = builtinFrameField(name, kDims);
    ASSERT_EQ(f.dims, kDims) << name;
    ASSERT_EQ(f.axes.size(), kDims.count()) << name;
    for (const auto& m : f.axes) {
      ASSERT_TRUE((m.transpose() * m).isApprox(Eigen::Matrix3f::Identity(), 1e-5f)) << name << "\n" << m;
      ASSERT_NEAR(m.determinant(), 1.f, 1e-5f) << name;
    }
  }
}

TEST(FrameField, CircleIsRadialAndTangential) {
  const FrameField f = builtinFrameField("circle", kDims);
  const double cx = (kDims.x - 1) / 2.0, cy = (kDims.y - 1) / 2.0;
  for (int k = 0; k < kDims.z; ++k)
    for (int j = 0; j < kDims.y; ++j)
      for (int i = 0; i < kDims.x; ++i) {
        const Eigen::Vector3f d(float(i - cx), float(j - cy), 0.f);
        if (d.norm() < 1.0f) continue;
        EXPECT_GT(std::abs(column(f, i, j, k, 1).dot(d.normalized())), 0.999f) << i << "," << j;
        EXPECT_LT(std::abs(column(f, i, j, k, 0).dot(d.normalized())), 1e-3f) << i << "," << j;
        EXPECT_NEAR(column(f, i, j, k, 2).z(), 1.f, 1e-6f);
      }
}

TEST(FrameField, CircleCentreIsIdentity) {
  const FrameField f = builtinFrameField("circle", {5, 5, 1});
  EXPECT_TRUE(f.at(2, 2, 0).isApprox(Eigen::Matrix3f::Identity()));
  EXPECT_FALSE(f.at(4, 2, 0).isApprox(Eigen::Matrix3f::Identity()));
}

TEST(FrameField, OvalFollowsTwoToOneEllipses) {
  const FrameField f = builtinFrameField("oval", kDims);
  const double cx = (kDims.x - 1) / 2.0, cy = (kDims.y - 1) / 2.0;
  for (int j = 0; j < kDims.y; ++j)
    for (int i = 0; i < kDims.x; ++i) {
      const double dx = i - cx, dy = j - cy;
      if (std::hypot(dx, dy) < 1) continue;
      // The tangent of the ellipse (dx / 2)^2 + dy^2 = c through (dx, dy) is (-4 dy, dx).
      const Eigen::Vector3f tangent = Eigen::Vector3f(float(-4 * dy), float(dx), 0.f).normalized();
      EXPECT_GT(std::abs(column(f, i, j, 3, 0).dot(tangent)), 0.999f) << i << "," << j;
    }
}

TEST(FrameField, SlantIsConstantFortyFiveDegrees) {
  const FrameField f = builtinFrameField("slant", kDims);
  const Eigen::Matrix3f first = f.axes.front();
  for (const auto& m : f.axes) ASSERT_TRUE(m.isApprox(first));
  const float s = std::sqrt(0.5f);
  EXPECT_TRUE(first.col(0).isApprox(Eigen::Vector3f(s, s, 0)));
  EXPECT_TRUE(first.col(1).isApprox(Eigen::Vector3f(-s, s, 0)));
  EXPECT_TRUE(first.col(2).isApprox(Eigen::Vector3f::UnitZ()));
}

TEST(FrameField, Slant3dTiltsOutOfThePlane) {
  const FrameField f = builtinFrameField("slant3d", kDims);
  const Eigen::Matrix3f first = f.axes.front();
  for (const auto& m : f.axes) ASSERT_TRUE(m.isApprox(first));
  EXPECT_NEAR(first.col(2).z(), std::sqrt(0.5f), 1e-6f);  // z tilted by 45 degrees
  const Eigen::Vector3f axis = Eigen::Vector3f(1, 1, 0).normalized();
  EXPECT_TRUE((first * axis).isApprox(axis));
}

TEST(FrameField, ZigzagAlternatesInBandsAlongX) {
  const Dims dims{64, 8, 2};  // half period max(4, 64 / 8) = 8
  const FrameField f = builtinFrameField("zigzag", dims);
  const float s = std::sqrt(0.5f);
  for (int i = 0; i < dims.x; ++i) {
    const bool up = (i / 8) % 2 == 0;
    const Eigen::Vector3f expected(s, up ? s : -s, 0);
    for (int k = 0; k < dims.z; ++k)
      for (int j = 0; j < dims.y; ++j) ASSERT_TRUE(column(f, i, j, k, 0).isApprox(expected)) << i;
  }
  // Small volumes keep bands of at least 4 voxels (period 8).
  const FrameField small = builtinFrameField("zigzag", {16, 2, 1});
  EXPECT_TRUE(small.at(3, 0, 0).isApprox(small.at(0, 0, 0)));
  EXPECT_FALSE(small.at(4, 0, 0).isApprox(small.at(0, 0, 0)));
  EXPECT_TRUE(small.at(8, 0, 0).isApprox(small.at(0, 0, 0)));
}

TEST(FrameField, UnknownNameThrowsListingTheValidOnes) {
  try {
    builtinFrameField("spiral", kDims);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("spiral"), std::string::npos) << what;
    for (const auto& name : builtinFrameFieldNames()) EXPECT_NE(what.find(name), std::string::npos) << what;
  }
  EXPECT_THROW(builtinFrameField("circle", {0, 4, 4}), InputError);
}

TEST(FrameField, WriteReadRoundTrip) {
  const std::string path = test::scratchPath("frameField", "circle.vdb").string();
  for (const auto& name : builtinFrameFieldNames()) {
    const FrameField f = builtinFrameField(name, kDims);
    writeFrameField(path, f);
    const FrameField back = readFrameField(path, kDims);
    ASSERT_EQ(back.dims, kDims);
    ASSERT_EQ(back.axes.size(), f.axes.size());
    for (std::size_t v = 0; v < f.axes.size(); ++v)
      ASSERT_LE((back.axes[v] - f.axes[v]).cwiseAbs().maxCoeff(), 1e-6f) << name << " voxel " << v;
  }
}

TEST(FrameField, ReadOrthonormalisesAndKeepsRightHanded) {
  const Dims dims{3, 2, 2};
  FrameField f{dims, std::vector<Eigen::Matrix3f>(dims.count(), Eigen::Matrix3f::Identity())};
  f.axes[1] = Eigen::Vector3f(2, 3, 0.5f).asDiagonal();  // scaled axes
  f.axes[2].col(1) = Eigen::Vector3f(0.1f, 1, 0);        // slightly sheared
  f.axes[3].col(2) = Eigen::Vector3f(0, 0, -1);          // left-handed
  const std::string path = test::scratchPath("frameField", "skewed.vdb").string();
  writeFrameField(path, f);
  const FrameField back = readFrameField(path, dims);
  for (const auto& m : back.axes) {
    ASSERT_TRUE((m.transpose() * m).isApprox(Eigen::Matrix3f::Identity(), 1e-5f)) << m;
    ASSERT_NEAR(m.determinant(), 1.f, 1e-5f);
  }
  EXPECT_TRUE(back.axes[1].isApprox(Eigen::Matrix3f::Identity(), 1e-6f));
  EXPECT_GT(back.axes[2].col(1).dot(Eigen::Vector3f(0.1f, 1, 0).normalized()), 0.99f);
  EXPECT_TRUE(back.axes[3].isApprox(Eigen::Matrix3f::Identity(), 1e-6f));
}

TEST(FrameField, MissingGridThrows) {
  const std::string path = test::scratchPath("frameField", "noAxisZ.vdb").string();
  writeFrameField(path, builtinFrameField("slant", kDims));
  patchBytes(path, "axis_z", "axis_w");  // the grid's name, stored verbatim in the file
  try {
    readFrameField(path, kDims);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("axis_z"), std::string::npos) << e.what();
  }
  // A solid's .vdb has no axis grids at all.
  const std::string solid = test::scratchPath("frameField", "solid.vdb").string();
  SolidVolume volume;
  volume.dims = {4, 4, 4};
  volume.color.assign(volume.dims.count(), Rgb{0.5f, 0.5f, 0.5f});
  writeVdb(solid, volume);
  EXPECT_THROW(readFrameField(solid, {4, 4, 4}), InputError);
}

TEST(FrameField, UnreadableFileThrows) {
  EXPECT_THROW(readFrameField("/nonexistent/field.vdb", kDims), InputError);
  const std::string path = test::scratchPath("frameField", "garbage.vdb").string();
  std::ofstream(path) << "not a vdb file";
  EXPECT_THROW(readFrameField(path, kDims), InputError);
}

TEST(FrameField, DegenerateFrameThrowsNamingTheVoxel) {
  const Dims dims{4, 3, 2};
  const std::string path = test::scratchPath("frameField", "degenerate.vdb").string();
  FrameField parallel{dims, std::vector<Eigen::Matrix3f>(dims.count(), Eigen::Matrix3f::Identity())};
  parallel.axes[dims.index(2, 1, 1)].col(1) = Eigen::Vector3f(1, 0, 1e-5f);  // y parallel to x
  writeFrameField(path, parallel);
  try {
    readFrameField(path, dims);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("(2,1,1)"), std::string::npos) << e.what();
  }
  FrameField zero{dims, std::vector<Eigen::Matrix3f>(dims.count(), Eigen::Matrix3f::Identity())};
  zero.axes[dims.index(3, 0, 0)].col(2).setZero();
  writeFrameField(path, zero);
  try {
    readFrameField(path, dims);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("(3,0,0)"), std::string::npos) << e.what();
  }
  // Reading a larger box than was written: the voxels outside take the zero background.
  writeFrameField(path, builtinFrameField("slant", dims));
  EXPECT_THROW(readFrameField(path, {5, 3, 2}), InputError);
}
