#pragma once
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "placement/placeLargestFirst.h"

namespace solidtex {

/// The placed particles as a sample of the solid's 3D sizes, whole: a block cut from a larger
/// placement (an open boundary) keeps the particles whose box centre lies in it, each with all its
/// voxels, so that neither the block's size nor its faces bias the sizes (a centre is a point, which
/// a face never cuts); a periodic or walled placement keeps every particle.
struct WholeParticleVolumes {
  std::vector<double> volumes;   ///< voxels of each kept particle, in placing order
  double cutShare = 0;           ///< share of the kept particles' voxels outside the block
  std::size_t cutParticles = 0;  ///< kept particles that cross the block's faces
};

/// The whole volumes of `placement`'s particles as WholeParticleVolumes defines them. Call it before
/// cropToCountedBox: the ids must cover the counted box and the particles carry their whole voxel
/// counts.
WholeParticleVolumes wholeParticleVolumes(const PlacementResult& placement);

/// Adds `whole` to a .vdb's metadata: `particle_volumes` (voxel counts separated by spaces),
/// `particle_volumes_cut_share` and `particle_volumes_cut_particles`.
void addWholeVolumesMetadata(const WholeParticleVolumes& whole, std::map<std::string, std::string>& metadata);

/// What addWholeVolumesMetadata wrote, or nothing when the metadata has no `particle_volumes`
/// (solids of older versions, truths). Throws InputError, naming `file`, for text that does not parse.
std::optional<WholeParticleVolumes> readWholeVolumesMetadata(
    const std::map<std::string, std::string>& metadata, const std::string& file);

}  // namespace solidtex
