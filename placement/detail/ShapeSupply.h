#pragma once
// Internal: the particle shapes of one placement phase, the next one made on another thread
// while the current one is tried at spots.
#include <array>
#include <cstdint>
#include <map>
#include <optional>

#include <tbb/task_group.h>

#include "common/Random.h"
#include "particles/ParticleFactory.h"
#include "placement/detail/shapeFit.h"

namespace solidtex::placement::detail {

/// A particle made for a photo particle's (width, height) box, ready to be tried at spots.
struct ReadyShape {
  ParticleSize size;
  FitShape fit;  ///< no voxels when the shape came out empty
};

/// An area bin, a (width, height) box of it and the phase of the photo particles with that box:
/// the pair that shapes are made for.
using ShapeKey = std::array<int, 4>;

/// A particle of `size` pixels made at `scale` voxels per pixel times its phase's size factor
/// (ParticleFactory::phaseScale of its source's phase), each edge at least one voxel.
VoxelShape makeScaled(const ParticleFactory& factory, const ParticleSize& size, double scale, Rng& rng);

/// The shapes of one phase. The n-th shape of a pair comes from its own stream (seed, phase, bin,
/// width, height, n), whenever and on whichever thread it is made, and a pair's shapes are taken
/// in that order: a shape made ahead for a pair that is then not tried is kept for its next turn.
class ShapeSupply {
public:
  ShapeSupply(const ParticleFactory& factory, std::uint64_t seed, int phase, double scale);
  ShapeSupply(const ShapeSupply&) = delete;
  ShapeSupply& operator=(const ShapeSupply&) = delete;
  ~ShapeSupply();

  /// Starts making the pair's next shape on another thread, unless one is kept for it already.
  void makeAhead(const ShapeKey& key);
  /// The pair's next shape: the one kept or being made for it, or made now.
  ReadyShape take(const ShapeKey& key);
  /// Drops what is kept for a pair that will not be tried again.
  void forget(const ShapeKey& key) { kept_.erase(key); }
  /// Waits for the shape being made; its error, if any, is thrown here.
  void finish() { aheadTask_.wait(); }

private:
  ReadyShape make(const ShapeKey& key, std::uint64_t n) const;
  void keepShapeMadeAhead();

  const ParticleFactory& factory_;
  std::uint64_t seed_;
  int phase_;
  double scale_;
  std::map<ShapeKey, std::uint64_t> made_;  ///< shapes made (or being made) per pair
  std::map<ShapeKey, ReadyShape> kept_;     ///< made ahead, not taken yet
  std::optional<ShapeKey> aheadKey_;        ///< the pair aheadTask_ makes a shape for
  ReadyShape ahead_;
  tbb::task_group aheadTask_;
};

}  // namespace solidtex::placement::detail
