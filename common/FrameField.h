#pragma once
#include <vector>

#include <Eigen/Core>

#include "common/Grid.h"

namespace solidtex {

/// Per output voxel, where each exemplar axis points in the output: column a of axes[v] is the
/// output-space direction of exemplar axis a (x, y, z). Identity everywhere = plain (isometric) synthesis.
struct FrameField {
  Dims dims;
  std::vector<Eigen::Matrix3f> axes;  ///< dims.count(), x fastest (Dims::index)

  const Eigen::Matrix3f& at(int i, int j, int k) const { return axes[dims.index(i, j, k)]; }
};

}  // namespace solidtex
