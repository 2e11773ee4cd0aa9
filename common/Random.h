#pragma once
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace solidtex {

/// The one random engine of solidtex; same seed, same sequence on every platform build.
using Rng = std::mt19937_64;

/// A seed for the stream number `stream` derived from `seed` (splitmix64), so parallel
/// work gets independent, thread-count-independent streams.
inline std::uint64_t deriveSeed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// A seed for a tuple of stream numbers: deriveSeed(deriveSeed(seed, a), b, ...), so that work
/// indexed by several numbers (phase, bin, pair, try) gets its own stream.
template <typename... Streams>
std::uint64_t deriveSeed(std::uint64_t seed, std::uint64_t stream, std::uint64_t next, Streams... rest) {
  return deriveSeed(deriveSeed(seed, stream), next, std::uint64_t(rest)...);
}

/// Uniform double in [0,1) computed from the engine's bits, identical across standard libraries
/// (std::uniform_real_distribution is not).
inline double uniform01(Rng& rng) { return double(rng() >> 11) * 0x1.0p-53; }

/// Uniform integer in [0, n), n > 0, identical across standard libraries.
inline std::uint64_t uniformIndex(Rng& rng, std::uint64_t n) {
  return std::uint64_t(uniform01(rng) * double(n));
}

/// A standard normal sample (Box-Muller), identical across standard libraries.
inline double standardNormal(Rng& rng) {
  const double u = 1 - uniform01(rng), v = uniform01(rng);  // u in (0,1]: log(u) is finite
  return std::sqrt(-2 * std::log(u)) * std::cos(2 * std::numbers::pi * v);
}

}  // namespace solidtex
