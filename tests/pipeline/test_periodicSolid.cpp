#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "common/distributionDistance.h"
#include "io/vdbIO.h"
#include "pipeline/particleSolidJob.h"
#include "tests/scratchPath.h"
#include "validation/sectionStatistics.h"

namespace solidtex {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 64;
constexpr int kBand = 3;  // voxels on each side of a face

SolidVolume solidWith(Boundary boundary, const std::string& photo = "gravel", int size = kSize) {
  const fs::path output =
      test::scratchPath("periodic_test", photo + "_" + std::string(boundaryName(boundary)) + ".vdb");
  ParticleSolidJob job;
  job.photo = std::string(SOLIDTEX_DATA_DIR) + "/particles/" + photo + ".png";
  job.output = output.string();
  job.dims = {size, size, size};
  job.boundary = boundary;
  job.progress = false;
  runParticleSolid(job);
  SolidVolume volume = readVdb(output.string());
  fs::remove(output);
  return volume;
}

// The plane k across `axis` of the volume tiled 2x2x2, seen through an N x N window that starts at
// `shift` on both in-plane axes: shift 0 is the volume's own plane, shift N/2 has the copies' faces
// through its middle.
cv::Mat planeWindow(const SolidVolume& volume, int axis, int k, int shift) {
  const int n = volume.dims.x;
  cv::Mat labels(n, n, CV_32S);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const int u = (c + shift) % n, w = (r + shift) % n;
      const Voxel v = axis == 0 ? Voxel{k, u, w} : axis == 1 ? Voxel{u, k, w} : Voxel{u, w, k};
      labels.at<std::int32_t>(r, c) = volume.particleId[volume.dims.index(v)];
    }
  return labels;
}

// The areas of the sections on every axis plane, through windows at `shift`.
std::vector<double> sectionAreas(const SolidVolume& volume, int shift) {
  SectionOptions options;
  options.minArea = 4;
  std::vector<double> areas;
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k < volume.dims.x; k += 2) {
      const SectionStatistics s = measureLabelImage(planeWindow(volume, axis, k, shift), options);
      areas.insert(areas.end(), s.areas.begin(), s.areas.end());
    }
  return areas;
}

// Whether voxel (x,y,z) lies in the slab of 2 kBand planes across `axis` centred between planes
// c - 1 and c (modulo the size: c = 0 is the slab across the face where copies meet).
bool inSlab(const Dims& d, int axis, int c, int x, int y, int z) {
  const int along = axis == 0 ? x : axis == 1 ? y : z;
  const int offset = ((along - c) % d.x + d.x) % d.x;
  return offset < kBand || offset >= d.x - kBand;
}

// Particle share of the slab of 2 kBand planes across `axis` centred between planes c - 1 and c
// (modulo the size: c = 0 is the slab across the face where copies meet).
double slabFraction(const SolidVolume& volume, int axis, int c) {
  const Dims& d = volume.dims;
  std::size_t occupied = 0, all = 0;
  for (int z = 0; z < d.z; ++z)
    for (int y = 0; y < d.y; ++y)
      for (int x = 0; x < d.x; ++x) {
        const int along = axis == 0 ? x : axis == 1 ? y : z;
        const int offset =
            ((along - c) % d.x + d.x) % d.x;  // 0..n-1, the slab is [n - kBand, n) and [0, kBand)
        if (offset >= kBand && offset < d.x - kBand) continue;
        ++all;
        occupied += volume.particleId[d.index(x, y, z)] > 0;
      }
  return double(occupied) / double(all);
}

struct SeamMeasures {
  double areaKs = 0, areaKsCritical = 0;  ///< sections across the faces against those inside
  double faceSlab = 0;                    ///< particle share of the slabs across the faces
  double slabLow = 1, slabHigh = 0;       ///< the least and most of the slabs inside the volume
};

SeamMeasures seamMeasures(const SolidVolume& volume) {
  SeamMeasures m;
  const std::vector<double> inside = sectionAreas(volume, 0), across = sectionAreas(volume, kSize / 2);
  m.areaKs = ksStatistic(inside, across);
  m.areaKsCritical = ksCritical95(inside.size(), across.size());
  for (int axis = 0; axis < 3; ++axis) {
    m.faceSlab += slabFraction(volume, axis, 0) / 3;
    for (int c = 2 * kBand; c <= kSize - 2 * kBand; c += kBand) {
      const double f = slabFraction(volume, axis, c);
      m.slabLow = std::min(m.slabLow, f);
      m.slabHigh = std::max(m.slabHigh, f);
    }
  }
  std::cout << "section area KS across/inside " << m.areaKs << " (critical " << m.areaKsCritical
            << "), slab fraction at the faces " << m.faceSlab << " (inside " << m.slabLow << "-" << m.slabHigh
            << ")\n";
  return m;
}

// Copies of a periodic solid side by side show no seam: the sections across the faces where they
// meet have the areas of those inside (two-sample KS under its 5 % critical value) and the slabs
// across those faces hold the share of particles the slabs inside do. The two other boundaries
// fail one measure each: open cuts particles at the faces, walls thin them out along them.
TEST(PeriodicParticleSolid, CopiesShowNoSeam) {
  const SeamMeasures periodic = seamMeasures(solidWith(Boundary::Periodic));
  EXPECT_LT(periodic.areaKs, periodic.areaKsCritical);
  EXPECT_GE(periodic.faceSlab, periodic.slabLow);
  EXPECT_LE(periodic.faceSlab, periodic.slabHigh);

  const SeamMeasures open = seamMeasures(solidWith(Boundary::Open));
  EXPECT_GT(open.areaKs, open.areaKsCritical);
  const SeamMeasures walls = seamMeasures(solidWith(Boundary::Walls));
  EXPECT_LT(walls.faceSlab, walls.slabLow);
}

// Mean and standard deviation of the background voxels' luminance in a slab (see inSlab).
std::pair<double, double> backgroundLuminance(const SolidVolume& volume, int axis, int c) {
  const Dims& d = volume.dims;
  double sum = 0, squares = 0;
  std::size_t n = 0;
  for (int z = 0; z < d.z; ++z)
    for (int y = 0; y < d.y; ++y)
      for (int x = 0; x < d.x; ++x) {
        const std::size_t i = d.index(x, y, z);
        if (volume.particleId[i] != 0 || !inSlab(d, axis, c, x, y, z)) continue;
        const Rgb& rgb = volume.color[i];
        const double l = (double(rgb[0]) + rgb[1] + rgb[2]) / 3;
        sum += l, squares += l * l, ++n;
      }
  const double mean = sum / double(n);
  return {mean, std::sqrt(std::max(0.0, squares / double(n) - mean * mean))};
}

// The background's colour does not change where copies meet. A projection of the photo's
// background cannot wrap, so it is cross-faded near the faces (ParticleColoring), which must
// neither brighten nor darken it nor change its contrast. The background's mean luminance and its
// spread in the slab across the face, on each axis and averaged over the three, lie within 4
// standard deviations of those of the slabs inside; the inside slabs' own spread is the photo's
// shading, which the projection lays into the volume. Leopard: the most shaded background of the
// photos (dividing the mean residual too, as a first version did, put the averaged face slab 5.5
// standard deviations brighter).
TEST(PeriodicParticleSolid, BackgroundIsEvenUpToTheFaces) {
  const SolidVolume volume = solidWith(Boundary::Periodic, "leopard", 96);
  const int n = volume.dims.x;
  std::vector<std::pair<double, double>> inside, faces;
  for (int axis = 0; axis < 3; ++axis) {
    faces.push_back(backgroundLuminance(volume, axis, 0));
    for (int c = 2 * kBand; c <= n - 2 * kBand; c += kBand)
      inside.push_back(backgroundLuminance(volume, axis, c));
  }
  const auto check = [&](double (*of)(const std::pair<double, double>&), const char* what) {
    double sum = 0, squares = 0, faceSum = 0;
    for (const auto& slab : inside) sum += of(slab), squares += of(slab) * of(slab);
    const double mean = sum / double(inside.size());
    const double sd = std::sqrt(squares / double(inside.size()) - mean * mean);
    for (const auto& slab : faces) {
      EXPECT_NEAR(of(slab), mean, 4 * sd) << what;
      faceSum += of(slab);
    }
    const double z = (faceSum / 3 - mean) / (sd / std::sqrt(3.0));
    std::cout << "background " << what << " at the faces " << faceSum / 3 << ", inside " << mean << " (sd "
              << sd << "): z " << z << "\n";
    EXPECT_LT(std::abs(z), 4) << what;
  };
  check([](const std::pair<double, double>& slab) { return slab.first; }, "mean luminance");
  check([](const std::pair<double, double>& slab) { return slab.second; }, "luminance spread");
}

}  // namespace
}  // namespace solidtex
