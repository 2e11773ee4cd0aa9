#pragma once
#include <functional>
#include <string>

namespace solidtex {

/// Reports a long computation's step: what it is doing, and the share of the work done so far in
/// [0, 1] (negative when it cannot tell). May be empty.
using Progress = std::function<void(const std::string& step, double fraction)>;

/// The share of a pyramid's work done after `level`'s `iteration` (both from 0), when level l
/// costs `voxels(l)` per iteration and every level runs `iterations`; each level 8x (3D) or 4x
/// (2D) the one before, so the finest dominates.
template <typename Voxels>
double pyramidFraction(int levels, int level, int iteration, int iterations, Voxels voxels) {
  double done = 0, total = 0;
  for (int l = 0; l < levels; ++l) {
    const double work = double(voxels(l)) * iterations;
    total += work;
    if (l < level) done += work;
  }
  done += double(voxels(level)) * (iteration + 1);
  return total > 0 ? done / total : -1;
}

}  // namespace solidtex
