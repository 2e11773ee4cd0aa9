#pragma once
// Checks every placement result must pass, for the placement tests.
#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "placement/placeLargestFirst.h"
#include "segmentation/ExemplarStats.h"

namespace solidtex::test {

// Whether the voxels with this id form one 6-connected piece.
inline bool connected(const PlacementResult& r, const PlacedParticle& p) {
  std::vector<std::size_t> queue;
  std::vector<std::uint8_t> seen(r.ids.size(), 0);
  for (std::size_t i = 0; i < r.ids.size() && queue.empty(); ++i)
    if (r.ids[i] == p.id) queue.push_back(i);
  if (queue.empty()) return false;
  seen[queue[0]] = 1;
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const Voxel v = r.dims.voxel(queue[q]);
    const int step[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    for (const auto& s : step) {
      if (!r.dims.contains(v.x + s[0], v.y + s[1], v.z + s[2])) continue;
      const std::size_t n = r.dims.index(v.x + s[0], v.y + s[1], v.z + s[2]);
      if (r.ids[n] == p.id && !seen[n]) {
        seen[n] = 1;
        queue.push_back(n);
      }
    }
  }
  return queue.size() == p.voxelCount;
}

// Ids, boxes, counts and histograms agree with each other; particles are whole and never overlap
// (each voxel holds one id, and every particle still has all its voxels).
inline void expectConsistent(const PlacementResult& r, const ExemplarStats& stats) {
  ASSERT_EQ(r.ids.size(), r.dims.count());
  std::vector<std::size_t> counted(r.particles.size() + 1, 0);
  for (std::size_t i = 0; i < r.ids.size(); ++i) {
    ASSERT_GE(r.ids[i], 0);
    ASSERT_LE(r.ids[i], int(r.particles.size()));
    ++counted[std::size_t(r.ids[i])];
    if (r.ids[i] == 0) continue;
    const PlacedParticle& p = r.particles[std::size_t(r.ids[i] - 1)];
    const Voxel v = r.dims.voxel(i);
    EXPECT_TRUE(v.x >= p.origin.x && v.y >= p.origin.y && v.z >= p.origin.z && v.x < p.origin.x + p.box.x &&
                v.y < p.origin.y + p.box.y && v.z < p.origin.z + p.box.z);
  }
  std::size_t occupied = 0;
  std::array<int, 10> perBin{};
  for (std::size_t i = 0; i < r.particles.size(); ++i) {
    const PlacedParticle& p = r.particles[i];
    EXPECT_EQ(p.id, int(i) + 1);
    EXPECT_EQ(counted[i + 1], p.voxelCount);
    EXPECT_TRUE(p.origin.x >= 0 && p.origin.y >= 0 && p.origin.z >= 0 && p.origin.x + p.box.x <= r.dims.x &&
                p.origin.y + p.box.y <= r.dims.y && p.origin.z + p.box.z <= r.dims.z)
        << "particle " << p.id << " is clipped by the walls";
    EXPECT_TRUE(connected(r, p)) << "particle " << p.id << " is not one piece";
    EXPECT_GT(stats.histogram.counts[std::size_t(p.bin)], 0);
    EXPECT_GE(p.source, 0);
    ++perBin[std::size_t(p.bin)];
    occupied += p.voxelCount;
  }
  EXPECT_EQ(perBin, r.placedPerBin);
  EXPECT_DOUBLE_EQ(r.volumeFraction, double(occupied) / double(r.dims.count()));
  if (!r.particles.empty()) {
    EXPECT_NEAR(std::accumulate(r.volumeHistogram.begin(), r.volumeHistogram.end(), 0.0), 1.0, 1e-9);
  }
  EXPECT_FALSE(r.stopReason.empty());
}

}  // namespace solidtex::test
