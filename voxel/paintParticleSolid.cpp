#include "voxel/paintParticleSolid.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "common/Random.h"

namespace solidtex {
namespace {

Rgb clamp01(const cv::Vec3f& c) {
  return {std::clamp(c[0], 0.f, 1.f), std::clamp(c[1], 0.f, 1.f), std::clamp(c[2], 0.f, 1.f)};
}

/// How a particle's 2D residual is laid into its 3D box: projected along one of its local axes,
/// chosen per particle, so no global direction is favoured.
struct ResidualProjection {
  int uAxis = 0, vAxis = 1;
};

cv::Vec3f residualAt(const Particle2D& source, const PlacedParticle& placed, const ResidualProjection& proj,
                     const int local[3]) {
  const int extent[3] = {placed.box.x, placed.box.y, placed.box.z};
  const int c = std::min(source.residual.cols - 1, local[proj.uAxis] * source.residual.cols / std::max(1, extent[proj.uAxis]));
  const int r = std::min(source.residual.rows - 1, local[proj.vAxis] * source.residual.rows / std::max(1, extent[proj.vAxis]));
  // Outside the photo particle's mask the residual is 0: the voxel keeps the mean colour.
  return source.residual.at<cv::Vec3f>(r, c);
}

/// Background residual for a voxel: each z-slice shows the photo's background residual under its
/// own random shift, so axis-z slices carry the photo's background grain.
cv::Vec3f backgroundResidualAt(const ExemplarStats& stats, const std::vector<cv::Point>& shifts, int x, int y, int z) {
  const cv::Mat& res = stats.backgroundResidual;
  const cv::Point s = shifts[std::size_t(z)];
  return res.at<cv::Vec3f>((y + s.y) % res.rows, (x + s.x) % res.cols);
}

} // namespace

SolidVolume paintParticleSolid(const ExemplarStats& stats, const PlacementResult& placement, std::uint64_t seed) {
  SolidVolume volume;
  const Dims dims = placement.dims;
  volume.dims = dims;
  volume.particleId = placement.ids;
  volume.density.assign(dims.count(), 0.f);
  volume.color.resize(dims.count());

  Rng rng(deriveSeed(seed, 0xC0102));
  std::vector<cv::Point> shifts(std::size_t(dims.z));
  for (auto& s : shifts)
    s = {int(uniformIndex(rng, std::uint64_t(stats.backgroundResidual.cols))),
         int(uniformIndex(rng, std::uint64_t(stats.backgroundResidual.rows)))};
  std::vector<ResidualProjection> projections(placement.particles.size());
  for (auto& p : projections) {
    const int skip = int(uniformIndex(rng, 3));  // the axis projected along
    p.uAxis = skip == 0 ? 1 : 0;
    p.vAxis = skip == 2 ? 1 : 2;
  }

  tbb::parallel_for(0, dims.z, [&](int z) {
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) {
        const std::size_t idx = dims.index(x, y, z);
        const std::int32_t id = placement.ids[idx];
        if (id == 0) {
          volume.color[idx] = clamp01(stats.backgroundColor + backgroundResidualAt(stats, shifts, x, y, z));
          continue;
        }
        const PlacedParticle& placed = placement.particles[std::size_t(id - 1)];
        const Particle2D& source = stats.particles[std::size_t(placed.source)];
        const int local[3] = {x - placed.origin.x, y - placed.origin.y, z - placed.origin.z};
        volume.density[idx] = 1.f;
        volume.color[idx] = clamp01(source.color + residualAt(source, placed, projections[std::size_t(id - 1)], local));
      }
  });
  return volume;
}

} // namespace solidtex
