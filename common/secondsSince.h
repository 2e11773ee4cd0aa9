#pragma once
#include <chrono>

namespace solidtex {

/// Wall-clock seconds from `start` until now, on the steady clock.
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace solidtex
