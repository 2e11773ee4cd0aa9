#include "segmentation/ExemplarStats.h"

#include <algorithm>

namespace solidtex {

int AreaHistogram::binOf(double area) const {
  const auto upper = std::upper_bound(edges.begin(), edges.end(), area);
  return std::clamp(int(upper - edges.begin()) - 1, 0, 9);
}

std::vector<std::size_t> statisticalParticles(const std::vector<Particle2D>& particles) {
  std::vector<std::size_t> inner, all;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    all.push_back(i);
    if (!particles[i].border) inner.push_back(i);
  }
  return inner.empty() ? all : inner;
}

}  // namespace solidtex
