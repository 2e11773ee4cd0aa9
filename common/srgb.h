#pragma once
#include <algorithm>
#include <cmath>

namespace solidtex {

// IEC 61966-2-1 transfer functions. Inputs are clamped to [0,1]: photos may carry out-of-range
// values (float EXR highlights, negative noise) that have no sRGB meaning.

/// sRGB in [0,1] to linear, per channel.
inline float srgbToLinear(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

/// Linear in [0,1] to sRGB, per channel.
inline float linearToSrgb(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace solidtex
