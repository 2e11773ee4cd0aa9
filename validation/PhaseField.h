#pragma once
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "common/Grid.h"

namespace solidtex {

/// One phase of an image (dims.z = 1) or a volume: inside[i] is 1 where voxel i is in the phase,
/// x fastest. What the materials descriptors (validation/) measure.
struct PhaseField {
  Dims dims;
  std::vector<std::uint8_t> inside;

  bool isImage() const { return dims.z == 1; }
  double fraction() const;
};

/// The particle phase (id > 0) or the matrix (id == 0) of a particle id volume.
PhaseField phaseOfIds(const Dims& dims, const std::vector<std::int32_t>& ids, bool particles);

/// The same of a label image (CV_32S, 0 = matrix), as a 2D field.
PhaseField phaseOfLabels(const cv::Mat& labels, bool particles);

}  // namespace solidtex
