#include "placement/cropPlacement.h"

#include <stdexcept>

namespace solidtex {

PlacementResult cropPlacement(const PlacementResult& placement, const Voxel& lo, const Dims& dims) {
  const Dims& from = placement.dims;
  if (lo.x < 0 || lo.y < 0 || lo.z < 0 || lo.x + dims.x > from.x || lo.y + dims.y > from.y ||
      lo.z + dims.z > from.z)
    throw std::invalid_argument("cropPlacement: the box is not inside the placement's volume");
  PlacementResult crop;
  crop.dims = dims;
  crop.ids.assign(dims.count(), 0);
  std::vector<std::size_t> inside(placement.particles.size() + 1, 0);  // per old id
  for (int z = 0; z < dims.z; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) {
        const std::int32_t id = placement.ids[from.index(lo.x + x, lo.y + y, lo.z + z)];
        crop.ids[dims.index(x, y, z)] = id;
        ++inside[std::size_t(id)];
      }
  std::vector<std::int32_t> renumbered(inside.size(), 0);
  std::size_t occupied = 0;
  for (const PlacedParticle& p : placement.particles) {
    if (inside[std::size_t(p.id)] == 0) continue;
    PlacedParticle kept = p;
    kept.id = int(crop.particles.size()) + 1;
    kept.origin = {p.origin.x - lo.x, p.origin.y - lo.y, p.origin.z - lo.z};
    kept.voxelCount = inside[std::size_t(p.id)];
    renumbered[std::size_t(p.id)] = kept.id;
    occupied += kept.voxelCount;
    ++crop.placedPerBin[std::size_t(kept.bin)];
    crop.particles.push_back(kept);
  }
  for (std::int32_t& id : crop.ids) id = renumbered[std::size_t(id)];
  crop.rejectedPerBin = placement.rejectedPerBin;
  crop.volumeFraction = double(occupied) / double(dims.count());
  for (std::size_t b = 0; b < crop.volumeHistogram.size(); ++b)
    crop.volumeHistogram[b] =
        crop.particles.empty() ? 0 : crop.placedPerBin[b] / double(crop.particles.size());
  crop.stopReason = placement.stopReason;
  crop.shrinkSteps = placement.shrinkSteps;
  crop.smallestScale = placement.smallestScale;
  crop.particlesBeforeShrinking = -1;
  if (placement.particlesBeforeShrinking >= 0) {
    crop.particlesBeforeShrinking = 0;
    for (const PlacedParticle& p : placement.particles)
      if (p.id <= placement.particlesBeforeShrinking && inside[std::size_t(p.id)] > 0)
        ++crop.particlesBeforeShrinking;
  }
  return crop;
}

}  // namespace solidtex
