#pragma once
#include <cmath>

namespace solidtex::synthesis {

/// sRGB in [0,1] to linear RGB, per channel (IEC 61966-2-1).
inline float srgbToLinearChannel(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

/// Linear RGB in [0,1] to sRGB, per channel (IEC 61966-2-1).
inline float linearToSrgbChannel(float c) {
  return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

} // namespace solidtex::synthesis
