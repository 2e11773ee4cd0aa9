#include "placement/cropToCountedBox.h"

#include <stdexcept>

namespace solidtex {

PlacementResult cropToCountedBox(PlacementResult placement) {
  const Box& box = placement.counted;
  const Dims dims = box.dims();
  if (placement.ids.size() != dims.count())
    throw std::invalid_argument("cropToCountedBox: the ids do not cover the counted box");
  PlacementResult crop;
  crop.dims = dims;
  crop.counted = Box::of(dims);
  std::vector<std::size_t> inside(placement.particles.size() + 1, 0);  // per old id
  for (const std::int32_t id : placement.ids) ++inside[std::size_t(id)];
  std::vector<std::int32_t> renumbered(inside.size(), 0);
  std::size_t occupied = 0;
  for (const PlacedParticle& p : placement.particles) {
    if (inside[std::size_t(p.id)] == 0) continue;
    PlacedParticle kept = p;
    kept.id = int(crop.particles.size()) + 1;
    kept.origin = {p.origin.x - box.lo.x, p.origin.y - box.lo.y, p.origin.z - box.lo.z};
    kept.voxelCount = inside[std::size_t(p.id)];
    renumbered[std::size_t(p.id)] = kept.id;
    occupied += kept.voxelCount;
    ++crop.placedPerBin[std::size_t(kept.bin)];
    crop.particles.push_back(kept);
  }
  crop.ids = std::move(placement.ids);
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
