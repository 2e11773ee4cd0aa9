#include "placement/detail/ShapeSupply.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace solidtex::placement::detail {
namespace {

constexpr std::uint64_t kShapeStream = 0x7368617065;  // "shape"

}  // namespace

VoxelShape makeScaled(const ParticleFactory& factory, const ParticleSize& size, double scale, Rng& rng) {
  const int phase = factory.phaseOf(size.source);
  const double kindScale = scale * factory.phaseScale(phase);
  const auto scaled = [kindScale](int pixels) { return int(std::max(1.0, std::round(pixels * kindScale))); };
  return factory.make(scaled(size.width), scaled(size.height), scaled(size.depth), rng, phase);
}

ShapeSupply::ShapeSupply(const ParticleFactory& factory, std::uint64_t seed, int phase, double scale)
    : factory_(factory), seed_(seed), phase_(phase), scale_(scale) {}

// Reached without finish() only when an exception unwinds the placement: the shape being made may
// still be on its way, and its own error is dropped, as one exception is on its way already.
ShapeSupply::~ShapeSupply() {
  try {
    aheadTask_.wait();
  } catch (...) {
  }
}

ReadyShape ShapeSupply::make(const ShapeKey& key, std::uint64_t n) const {
  // Sides stay below 2^16: the phase above them keeps the one-phase streams as they were.
  Rng rng(deriveSeed(seed_, kShapeStream + std::uint64_t(phase_), key[0], key[1],
                     std::uint64_t(key[2]) + (std::uint64_t(key[3]) << 16), n));
  ReadyShape shape;
  shape.size = factory_.pickDepth(key[1], key[2], rng, key[3]);
  const VoxelShape voxels = makeScaled(factory_, shape.size, scale_, rng);
  if (voxels.voxelCount() > 0) shape.fit = prepareShape(voxels);
  return shape;
}

void ShapeSupply::makeAhead(const ShapeKey& key) {
  keepShapeMadeAhead();
  if (kept_.count(key)) return;
  aheadKey_ = key;
  aheadTask_.run([this, key, n = made_[key]++] { ahead_ = make(key, n); });
}

void ShapeSupply::keepShapeMadeAhead() {
  aheadTask_.wait();
  if (aheadKey_) kept_.emplace(*aheadKey_, std::move(ahead_));
  aheadKey_.reset();
}

ReadyShape ShapeSupply::take(const ShapeKey& key) {
  if (aheadKey_ == key) keepShapeMadeAhead();
  const auto kept = kept_.find(key);
  if (kept == kept_.end()) return make(key, made_[key]++);
  ReadyShape shape = std::move(kept->second);
  kept_.erase(kept);
  return shape;
}

}  // namespace solidtex::placement::detail
