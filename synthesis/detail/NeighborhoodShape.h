#pragma once

namespace solidtex::synthesis {

/// A square size x size neighbourhood of RGB pixels around a centre pixel. Offsets run from lo()
/// to hi() on both axes (for even sizes the centre sits just right/below the middle). Vectors are
/// laid out row by row (offset j outer, i inner), 3 channels per pixel: dims() = size*size*3.
struct NeighborhoodShape {
  int size = 8;

  int lo() const { return -(size / 2); }
  int hi() const { return lo() + size - 1; }
  int pixels() const { return size * size; }
  int dims() const { return size * size * 3; }
};

}  // namespace solidtex::synthesis
