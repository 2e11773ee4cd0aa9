#include "mesh/particleMeshes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include <tbb/parallel_for.h>
#include <Eigen/Geometry>

#include "mesh/clipToBox.h"
#include "mesh/largestPiece.h"
#include "mesh/simplifyMesh.h"
#include "particles/voxelizeHull.h"

namespace solidtex {
namespace {

// A hull is meshed as finely for a particle of 4 voxels as for one of 100 (10^4 triangles when
// smoothed): each particle takes the hull simplified to about two triangles per voxel face of its
// surface, edges about 1.4 voxels long. That takes gravel at 128^3 from 72 million triangles to a few.
constexpr double kTrianglesPerArea = 2;
constexpr int kCoarsestLevel = 6;  // 2^6 triangles: a few voxels' particle is still round
constexpr int kFinestLevel = 30;

// The detail level a particle needs: level k has at most 2^k triangles.
int levelOf(const HullMesh& hull, const HullPose& pose) {
  double area = 0;
  for (const auto& [a, b, c] : hull.triangles) {
    const Eigen::Vector3d& p = hull.vertices[std::size_t(a)];
    area += (pose.linear * (hull.vertices[std::size_t(b)] - p))
                .cross(pose.linear * (hull.vertices[std::size_t(c)] - p))
                .norm();
  }
  area /= 2;
  return std::clamp(int(std::ceil(std::log2(std::max(1.0, kTrianglesPerArea * area)))), kCoarsestLevel,
                    kFinestLevel);
}

using LevelKey = std::pair<int, int>;  // hull, level

// The largest piece of each hull (the one voxelize keeps) at every level some particle needs.
std::map<LevelKey, HullMesh> hullLevels(const std::vector<LevelKey>& needed,
                                        const std::vector<HullMesh>& hulls) {
  std::map<LevelKey, HullMesh> levels;
  for (const LevelKey& key : needed) levels[key];
  std::vector<std::pair<const LevelKey, HullMesh>*> todo;
  for (auto& entry : levels) todo.push_back(&entry);
  tbb::parallel_for(std::size_t(0), todo.size(), [&](std::size_t i) {
    const auto& [hull, level] = todo[i]->first;
    todo[i]->second = simplifyMesh(largestPiece(hulls[std::size_t(hull)]), std::size_t(1) << level);
  });
  return levels;
}

// The posed surface cut to the volume. Where simplifying made it touch itself at the cut, the hull
// as it was; where even that cannot be cut (CGAL finds it not manifold), the whole surface.
HullMesh cutToVolume(const HullMesh& simplified, const HullMesh& hull, const HullPose& pose,
                     const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const HullMesh posed = posedHull(simplified, pose);
  try {
    return clipToBox(posed, lo, hi);
  } catch (const std::runtime_error&) {
  }
  const HullMesh whole = posedHull(largestPiece(hull), pose);
  try {
    if (whole.triangles.size() != posed.triangles.size()) return clipToBox(whole, lo, hi);
  } catch (const std::runtime_error&) {
  }
  return posed;
}

}  // namespace

std::vector<ParticleMesh> particleMeshes(const PlacementResult& placement,
                                         const std::vector<HullMesh>& hulls) {
  for (const PlacedParticle& p : placement.particles)
    if (p.pose.hull < 0 || std::size_t(p.pose.hull) >= hulls.size())
      throw std::invalid_argument("particleMeshes: particle " + std::to_string(p.id) +
                                  " was not made from one of the given hulls");
  std::vector<LevelKey> keys(placement.particles.size());
  tbb::parallel_for(std::size_t(0), keys.size(), [&](std::size_t i) {
    const HullPose& pose = placement.particles[i].pose;
    keys[i] = {pose.hull, levelOf(hulls[std::size_t(pose.hull)], pose)};
  });
  const std::map<LevelKey, HullMesh> levels = hullLevels(keys, hulls);
  const Eigen::Vector3d lo = Eigen::Vector3d::Constant(-0.5);
  const Eigen::Vector3d hi = Eigen::Vector3d(placement.dims.x, placement.dims.y, placement.dims.z) + lo;
  std::vector<ParticleMesh> meshes(placement.particles.size());
  tbb::parallel_for(std::size_t(0), meshes.size(), [&](std::size_t i) {
    const PlacedParticle& p = placement.particles[i];
    // Local voxel (i,j,k) is the cube from (i,j,k); in the index space it is centred at origin + (i,j,k).
    HullPose pose = p.pose;
    pose.offset += Eigen::Vector3d(p.origin.x, p.origin.y, p.origin.z) + lo;
    const HullMesh& simplified = levels.at(keys[i]);
    meshes[i] = {p.id,
                 {},
                 placement.periodic ? posedHull(simplified, pose)
                                    : cutToVolume(simplified, hulls[std::size_t(p.pose.hull)], pose, lo, hi)};
  });
  return meshes;
}

}  // namespace solidtex
