#pragma once
#include <cstdint>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "common/Grid.h"
#include "common/SolidVolume.h"

namespace solidtex {

/// A square patch of `side` x `side` pixels, each the mean of `scale` x `scale` samples, so that one
/// patch spans side * scale samples; as a vector of side * side sRGB triples, row-major.
struct PatchGeometry {
  int side = 8;
  int scale = 1;
  int span() const { return side * scale; }
  int dims() const { return side * side * 3; }
};

/// A volume's colours as sRGB in [0,1], x fastest, 3 interleaved channels.
struct SrgbVolume {
  Dims dims;
  std::vector<float> rgb;
};

/// The sRGB form of a volume's linear colours.
SrgbVolume srgbVolumeOf(const SolidVolume& volume);

/// How many patches lie wholly inside an image of this size.
std::int64_t patchPositions(const cv::Size& image, PatchGeometry geometry);

/// Whether axis-aligned patches fit in the volume's slices.
bool axisPatchesFit(const Dims& dims, PatchGeometry geometry);
/// Whether patches on planes of every orientation fit inside the volume.
bool obliquePatchesFit(const Dims& dims, PatchGeometry geometry);

/// `count` patches of an sRGB image (CV_32FC3, RGB) at distinct positions in random order, as the
/// columns of a geometry.dims() x count matrix; every position when count >= patchPositions.
Eigen::MatrixXf imagePatches(const cv::Mat& srgb, PatchGeometry geometry, int count, std::uint64_t seed);

/// `count` patches of slices orthogonal to x, y and z in turn (or to `onlyAxis` alone when it is
/// 0, 1 or 2), at random positions inside the volume; x slices with y across and z down, y slices x
/// across and z down, z slices x across and y down.
Eigen::MatrixXf axisSlicePatches(const SrgbVolume& volume, PatchGeometry geometry, int count,
                                 std::uint64_t seed, int onlyAxis = -1);

/// `count` patches of randomly rotated planes through random points, wholly inside the volume,
/// sampled trilinearly.
Eigen::MatrixXf obliqueSlicePatches(const SrgbVolume& volume, PatchGeometry geometry, int count,
                                    std::uint64_t seed);

}  // namespace solidtex
