#include "validation/slicePatches.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include <tbb/parallel_for.h>
#include <Eigen/Geometry>

#include "common/Random.h"
#include "common/srgb.h"

namespace solidtex {
namespace {

// Writes the patch whose top-left sample is at (0, 0) of `sample(i, j, out)`, block-averaging
// scale x scale samples per patch pixel.
template <typename Sample>
void gatherPatch(PatchGeometry g, const Sample& sample, float* out) {
  const float weight = 1.0f / float(g.scale * g.scale);
  float rgb[3];
  for (int r = 0; r < g.side; ++r)
    for (int c = 0; c < g.side; ++c, out += 3) {
      out[0] = out[1] = out[2] = 0.0f;
      for (int b = 0; b < g.scale; ++b)
        for (int a = 0; a < g.scale; ++a) {
          sample(c * g.scale + a, r * g.scale + b, rgb);
          for (int k = 0; k < 3; ++k) out[k] += weight * rgb[k];
        }
    }
}

// Half the diagonal of a patch: its farthest sample from the centre.
double patchRadius(PatchGeometry g) { return double(g.span() - 1) / std::sqrt(2.0); }

void sampleTrilinear(const SrgbVolume& v, const Eigen::Vector3d& p, float* out) {
  int i0[3];
  double f[3];
  const int extent[3] = {v.dims.x, v.dims.y, v.dims.z};
  for (int a = 0; a < 3; ++a) {
    i0[a] = std::clamp(int(std::floor(p[a])), 0, std::max(0, extent[a] - 2));
    f[a] = std::clamp(p[a] - double(i0[a]), 0.0, 1.0);
  }
  double acc[3] = {0, 0, 0};
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const double w = (dz ? f[2] : 1 - f[2]) * (dy ? f[1] : 1 - f[1]) * (dx ? f[0] : 1 - f[0]);
        if (w == 0) continue;
        const float* c = v.rgb.data() + 3 * v.dims.index(i0[0] + dx, i0[1] + dy, i0[2] + dz);
        for (int k = 0; k < 3; ++k) acc[k] += w * c[k];
      }
  for (int k = 0; k < 3; ++k) out[k] = float(acc[k]);
}

}  // namespace

SrgbVolume srgbVolumeOf(const SolidVolume& volume) {
  SrgbVolume v{volume.dims, std::vector<float>(volume.color.size() * 3)};
  tbb::parallel_for(std::size_t(0), volume.color.size(), [&](std::size_t i) {
    for (int k = 0; k < 3; ++k) v.rgb[3 * i + k] = linearToSrgb(volume.color[i][k]);
  });
  return v;
}

std::int64_t patchPositions(const cv::Size& image, PatchGeometry g) {
  return std::int64_t(std::max(0, image.width - g.span() + 1)) * std::max(0, image.height - g.span() + 1);
}

bool axisPatchesFit(const Dims& dims, PatchGeometry g) {
  const int spans = int(dims.x >= g.span()) + int(dims.y >= g.span()) + int(dims.z >= g.span());
  return spans == 3;
}

bool obliquePatchesFit(const Dims& dims, PatchGeometry g) {
  return double(std::min({dims.x, dims.y, dims.z}) - 1) >= 2 * patchRadius(g);
}

Eigen::MatrixXf imagePatches(const cv::Mat& srgb, PatchGeometry g, int count, std::uint64_t seed) {
  const int columns = srgb.cols - g.span() + 1;
  std::vector<std::int64_t> positions(std::size_t(patchPositions(srgb.size(), g)));
  std::iota(positions.begin(), positions.end(), std::int64_t(0));
  Rng rng(seed);
  const std::size_t taken = std::min(positions.size(), std::size_t(std::max(count, 0)));
  for (std::size_t i = 0; i < taken; ++i)  // partial Fisher-Yates: a random subset in random order
    std::swap(positions[i], positions[i + uniformIndex(rng, positions.size() - i)]);
  Eigen::MatrixXf patches(g.dims(), Eigen::Index(taken));
  tbb::parallel_for(std::size_t(0), taken, [&](std::size_t p) {
    const int x0 = int(positions[p] % columns), y0 = int(positions[p] / columns);
    gatherPatch(
        g,
        [&](int i, int j, float* out) {
          const cv::Vec3f& c = srgb.at<cv::Vec3f>(y0 + j, x0 + i);
          out[0] = c[0], out[1] = c[1], out[2] = c[2];
        },
        patches.col(Eigen::Index(p)).data());
  });
  return patches;
}

Eigen::MatrixXf axisSlicePatches(const SrgbVolume& v, PatchGeometry g, int count, std::uint64_t seed,
                                 int onlyAxis) {
  struct Origin {
    int axis, x, y, z;
  };
  const int extent[3] = {v.dims.x, v.dims.y, v.dims.z};
  Rng rng(seed);
  std::vector<Origin> origins(static_cast<std::size_t>(count));
  for (int p = 0; p < count; ++p) {
    const int axis = onlyAxis >= 0 ? onlyAxis : p % 3;
    int corner[3];
    for (int a = 0; a < 3; ++a)
      corner[a] = int(uniformIndex(rng, std::uint64_t(a == axis ? extent[a] : extent[a] - g.span() + 1)));
    origins[std::size_t(p)] = {axis, corner[0], corner[1], corner[2]};
  }
  Eigen::MatrixXf patches(g.dims(), count);
  tbb::parallel_for(0, count, [&](int p) {
    const Origin& o = origins[std::size_t(p)];
    // The plane's in-plane axes: (x, y) for z slices, (x, z) for y slices, (y, z) for x slices.
    const int u = o.axis == 0 ? 1 : 0, w = o.axis == 2 ? 1 : 2;
    gatherPatch(
        g,
        [&](int i, int j, float* out) {
          int at[3] = {o.x, o.y, o.z};
          at[u] += i;
          at[w] += j;
          const float* c = v.rgb.data() + 3 * v.dims.index(at[0], at[1], at[2]);
          out[0] = c[0], out[1] = c[1], out[2] = c[2];
        },
        patches.col(p).data());
  });
  return patches;
}

Eigen::MatrixXf obliqueSlicePatches(const SrgbVolume& v, PatchGeometry g, int count, std::uint64_t seed) {
  struct Plane {
    Eigen::Vector3d corner, u, w;
  };
  const double radius = patchRadius(g), half = 0.5 * double(g.span() - 1);
  const int extent[3] = {v.dims.x, v.dims.y, v.dims.z};
  Rng rng(seed);
  std::vector<Plane> planes(static_cast<std::size_t>(count));
  for (int p = 0; p < count; ++p) {
    Eigen::Quaterniond q(standardNormal(rng), standardNormal(rng), standardNormal(rng), standardNormal(rng));
    q.normalize();
    const Eigen::Matrix3d R = q.toRotationMatrix();
    Eigen::Vector3d centre;
    for (int a = 0; a < 3; ++a) centre[a] = radius + uniform01(rng) * (double(extent[a] - 1) - 2 * radius);
    planes[std::size_t(p)] = {centre - half * (R.col(0) + R.col(1)), R.col(0), R.col(1)};
  }
  Eigen::MatrixXf patches(g.dims(), count);
  tbb::parallel_for(0, count, [&](int p) {
    const Plane& plane = planes[std::size_t(p)];
    gatherPatch(
        g,
        [&](int i, int j, float* out) {
          sampleTrilinear(v, plane.corner + double(i) * plane.u + double(j) * plane.w, out);
        },
        patches.col(p).data());
  });
  return patches;
}

}  // namespace solidtex
