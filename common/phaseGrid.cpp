#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "common/SolidVolume.h"

namespace solidtex {

std::vector<std::uint8_t> phaseGrid(const SolidVolume& volume) {
  if (volume.particlePhase.empty()) return {};
  if (volume.particleId.size() != volume.dims.count())
    throw std::logic_error("phaseGrid: the phases are the particles', and the volume has no particle ids");
  std::vector<std::uint8_t> out(volume.particleId.size());
  const std::vector<std::uint8_t>& phaseOf = volume.particlePhase;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.size()),
                    [&](const tbb::blocked_range<std::size_t>& run) {
                      for (std::size_t i = run.begin(); i != run.end(); ++i) {
                        const std::int32_t id = volume.particleId[i];
                        out[i] = id > 0 && std::size_t(id) <= phaseOf.size()
                                     ? std::uint8_t(phaseOf[std::size_t(id) - 1] + 1)
                                     : 0;
                      }
                    });
  return out;
}

}  // namespace solidtex
