#include <stdexcept>

#include <tbb/parallel_for.h>

#include "common/SolidVolume.h"

namespace solidtex {

void paintColor(SolidVolume& volume) {
  if (!volume.coloring || !volume.color.empty()) return;
  if (volume.particleId.size() != volume.dims.count())
    throw std::logic_error("paintColor: colours are painted from the particle ids, which it lacks");
  const Dims d = volume.dims;
  const VolumeColoring& coloring = *volume.coloring;
  volume.color.resize(d.count());
  tbb::parallel_for(0, d.z, [&](int z) {
    for (int y = 0; y < d.y; ++y)
      for (int x = 0; x < d.x; ++x) {
        const std::size_t i = d.index(x, y, z);
        volume.color[i] = coloring.at(x, y, z, volume.particleId[i]);
      }
  });
  volume.coloring.reset();
}

}  // namespace solidtex
