#pragma once
#include <string>

namespace solidtex {

/// The edge of a voxel in some unit, for exports that carry a calibration.
struct VoxelSize {
  double size = 1;
  std::string unit = "voxel";  ///< e.g. "pixel": the photo's pixels, which a user may know in µm
};

}  // namespace solidtex
