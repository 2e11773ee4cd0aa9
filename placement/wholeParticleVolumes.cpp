#include "placement/wholeParticleVolumes.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "common/Error.h"

namespace solidtex {

WholeParticleVolumes wholeParticleVolumes(const PlacementResult& placement) {
  const Box& box = placement.counted;
  if (placement.ids.size() != box.dims().count())
    throw std::invalid_argument("wholeParticleVolumes: the ids do not cover the counted box");
  const bool block = !placement.periodic && !(box == Box::of(placement.dims));
  std::vector<std::size_t> inside(placement.particles.size() + 1, 0);  // per id
  if (block)
    for (const std::int32_t id : placement.ids) ++inside[std::size_t(id)];
  WholeParticleVolumes out;
  double kept = 0, keptInside = 0;
  for (const PlacedParticle& p : placement.particles) {
    // Twice the box centre, so that the test is exact in integers.
    const int cx = 2 * p.origin.x + p.box.x, cy = 2 * p.origin.y + p.box.y, cz = 2 * p.origin.z + p.box.z;
    if (block && !(cx >= 2 * box.lo.x && cx < 2 * box.hi.x && cy >= 2 * box.lo.y && cy < 2 * box.hi.y &&
                   cz >= 2 * box.lo.z && cz < 2 * box.hi.z))
      continue;
    out.volumes.push_back(double(p.voxelCount));
    kept += double(p.voxelCount);
    const std::size_t in = block ? inside[std::size_t(p.id)] : p.voxelCount;
    keptInside += double(in);
    out.cutParticles += in < p.voxelCount;
  }
  out.cutShare = kept > 0 ? 1.0 - keptInside / kept : 0.0;
  return out;
}

void addWholeVolumesMetadata(const WholeParticleVolumes& whole,
                             std::map<std::string, std::string>& metadata) {
  std::string text;
  text.reserve(whole.volumes.size() * 6);
  for (const double v : whole.volumes) (text.empty() ? text : text += ' ') += std::to_string(std::llround(v));
  char share[32];
  std::snprintf(share, sizeof share, "%.6f", whole.cutShare);
  metadata["particle_volumes"] = text;
  metadata["particle_volumes_cut_share"] = share;
  metadata["particle_volumes_cut_particles"] = std::to_string(whole.cutParticles);
}

std::optional<WholeParticleVolumes> readWholeVolumesMetadata(
    const std::map<std::string, std::string>& metadata, const std::string& file) {
  const auto text = metadata.find("particle_volumes");
  if (text == metadata.end()) return std::nullopt;
  const auto number = [&](const char* key, double most) {
    const auto it = metadata.find(key);
    char* end = nullptr;
    const double value = it == metadata.end() ? 0.0 : std::strtod(it->second.c_str(), &end);
    if (it != metadata.end() && (end == it->second.c_str() || *end != '\0' || !(value >= 0 && value <= most)))
      throw InputError(file + ": metadata " + key + " is not a number in [0, " + std::to_string(most) + "]");
    return value;
  };
  WholeParticleVolumes whole;
  std::istringstream in(text->second);
  for (long long v = 0; in >> v;) {
    if (v <= 0) throw InputError(file + ": metadata particle_volumes holds a volume that is not positive");
    whole.volumes.push_back(double(v));
  }
  if (!in.eof()) throw InputError(file + ": metadata particle_volumes is not a list of voxel counts");
  whole.cutShare = number("particle_volumes_cut_share", 1);
  whole.cutParticles = std::size_t(number("particle_volumes_cut_particles", double(whole.volumes.size())));
  return whole;
}

}  // namespace solidtex
