#pragma once

namespace solidtex::synthesis::detail {

/// A square size x size neighbourhood of pixels around a centre pixel. Offsets run from lo() to hi()
/// on both axes (for even sizes the centre sits just right/below the middle). Vectors are laid out
/// row by row (offset j outer, i inner), channels() floats per pixel: its RGB colour, or with
/// `wavelet` Pan et al.'s eq. 3 features, the Haar coefficients (approximation, horizontal,
/// vertical and diagonal detail, RGB each) of the 2x2 block whose top-left pixel it is, so a
/// neighbourhood reads one pixel beyond hi() on both axes.
struct NeighborhoodShape {
  int size = 8;
  bool wavelet = false;

  int lo() const { return -(size / 2); }
  int hi() const { return lo() + size - 1; }
  int pixels() const { return size * size; }
  int channels() const { return wavelet ? 12 : 3; }
  int dims() const { return size * size * channels(); }
  /// Pixels a neighbourhood reads along each axis.
  int extent() const { return size + (wavelet ? 1 : 0); }
};

/// Writes one pixel's features (shape.channels() floats) from the RGB colours of the 2x2 block whose
/// top-left pixel it is (p00, right p10, below p01, diagonal p11); advances `out`.
inline void writePixelFeatures(const NeighborhoodShape& shape, const float* p00, const float* p10,
                               const float* p01, const float* p11, float*& out) {
  if (!shape.wavelet) {
    for (int c = 0; c < 3; ++c) *out++ = p00[c];
    return;
  }
  for (int c = 0; c < 3; ++c) out[c] = 0.25f * (p00[c] + p10[c] + p01[c] + p11[c]);
  for (int c = 0; c < 3; ++c) out[3 + c] = 0.25f * (p00[c] - p10[c] + p01[c] - p11[c]);
  for (int c = 0; c < 3; ++c) out[6 + c] = 0.25f * (p00[c] + p10[c] - p01[c] - p11[c]);
  for (int c = 0; c < 3; ++c) out[9 + c] = 0.25f * (p00[c] - p10[c] - p01[c] + p11[c]);
  out += 12;
}

}  // namespace solidtex::synthesis::detail
