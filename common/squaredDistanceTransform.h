#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "common/Grid.h"

namespace solidtex {

/// A sample that is no site: no feature voxel on the line.
constexpr std::uint32_t kNoSite = 0x3fffffff;

/// Lower envelope of the parabolas (q - p)^2 + f[p] of one line's sites (Felzenszwalb & Huttenlocher).
class LowerEnvelope {
public:
  explicit LowerEnvelope(int n) : apex_(std::size_t(n)), from_(std::size_t(n)), value_(std::size_t(n)) {}

  /// Sites f[0], f[stride], ... (n of them) at positions origin, origin+1, ...; kNoSite samples are none.
  void build(const std::uint32_t* f, int n, std::ptrdiff_t stride, int origin) {
    top_ = -1;
    cursor_ = 0;
    for (int i = 0; i < n; ++i) {
      const std::uint32_t fi = f[i * stride];
      if (fi >= kNoSite) continue;
      const int q = origin + i;
      const double lifted = double(fi) + double(q) * q;
      double from = -std::numeric_limits<double>::infinity();
      while (top_ >= 0) {
        const int p = apex_[std::size_t(top_)];
        from = (lifted - (double(value_[std::size_t(top_)]) + double(p) * p)) / (2.0 * (q - p));
        if (from > from_[std::size_t(top_)]) break;
        --top_;
        from = -std::numeric_limits<double>::infinity();
      }
      ++top_;
      apex_[std::size_t(top_)] = q;
      from_[std::size_t(top_)] = from;
      value_[std::size_t(top_)] = fi;
    }
  }

  bool empty() const { return top_ < 0; }

  /// The envelope at q; successive calls must not decrease q.
  std::uint32_t at(int q) {
    while (cursor_ < top_ && from_[std::size_t(cursor_) + 1] < q) ++cursor_;
    const std::int64_t d = q - apex_[std::size_t(cursor_)];
    return std::uint32_t(d * d + value_[std::size_t(cursor_)]);
  }

private:
  std::vector<int> apex_;
  std::vector<double> from_;
  std::vector<std::uint32_t> value_;
  int top_ = -1, cursor_ = 0;
};

/// In place: f[i] = min_j f[j] + (i-j)^2 over the samples f[0], f[stride], ... of one line.
inline void transformLine(std::uint32_t* f, int n, std::ptrdiff_t stride, LowerEnvelope& envelope) {
  envelope.build(f, n, stride, 0);
  if (envelope.empty()) return;
  for (int q = 0; q < n; ++q) f[q * stride] = envelope.at(q);
}

/// Exact squared Euclidean distance from every voxel to the nearest voxel where `isSite` is 1, 0 on
/// sites, kNoSite everywhere when there is none. Separable (three passes of transformLine, TBB).
std::vector<std::uint32_t> squaredDistanceToSites(const Dims& dims, const std::vector<std::uint8_t>& isSite);

/// The same into `out` (resized to dims.count()), which a caller that transforms many fields reuses.
void squaredDistanceToSites(const Dims& dims, const std::vector<std::uint8_t>& isSite,
                            std::vector<std::uint32_t>& out);

}  // namespace solidtex
