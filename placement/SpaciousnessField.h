#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/Grid.h"
#include "common/Random.h"

namespace solidtex {

/// How spaciousness is computed (paper 3.7). A new kind is a value here, its row in the table of
/// SpaciousnessField.cpp, and its field's own file.
enum class PlacerKind { Discrete, Brute, Edt, Delaunay };

/// Every kind, in the table's order: what parsers, help texts and evaluations go through.
const std::vector<PlacerKind>& placerKinds();

/// Parses a kind's name; throws OptionError naming the kinds otherwise.
PlacerKind parsePlacerKind(const std::string& name);
const char* placerName(PlacerKind kind);
/// "discrete, brute, edt or delaunay": every kind's name, as help texts list them.
std::string placerNames();

/// Spaciousness of every voxel of a volume: the radius, in voxels, of the largest ball centred at
/// the voxel's centre that holds no occupied voxel centre. The walls count as occupied layers at
/// index -1 and N on each axis, so in an empty volume voxel i has min(i+1, N-i) per axis.
/// Values are capped at the field's maxRadius (the paper's sqrt(3)D/2): nothing larger is ever asked for.
/// A periodic field has no walls: the volume is a 3D torus whose opposite faces meet, distances are
/// taken around it, and insert() takes voxels anywhere, each standing for its image modulo dims (a
/// particle that crosses a face is passed whole, running past it).
class SpaciousnessField {
public:
  virtual ~SpaciousnessField() = default;
  virtual PlacerKind kind() const = 0;
  /// The volume the field covers.
  virtual Dims dims() const = 0;
  /// Whether the volume is a 3D torus (no walls).
  virtual bool periodic() const = 0;
  /// The cap of every value.
  virtual float maxRadius() const = 0;
  /// Marks a newly placed particle's voxels (volume coordinates) occupied and updates the field.
  virtual void insert(const std::vector<Voxel>& voxels) = 0;
  /// This field's spaciousness of v: never above the exact value (brute, edt: equal to it;
  /// discrete: at least the exact value / sqrt(3); Delaunay: at least the exact value less 1.02).
  virtual float at(const Voxel& v) const = 0;
  /// Up to maxCount distinct free candidate spots whose value is at least `radius`, the smallest
  /// value first (best fit), equal values in an order drawn from rng. A spot's spaciousness is at
  /// least its value less slack().
  virtual std::vector<Voxel> bestFit(float radius, int maxCount, Rng& rng) = 0;
  /// Up to maxCount free candidate spots drawn uniformly (with replacement) among those valued at
  /// least `radius`, in the order drawn: a random spot that may hold a particle, not the tightest.
  virtual std::vector<Voxel> randomFit(float radius, int maxCount, Rng& rng) = 0;
  /// How far bestFit's values may exceed the spaciousness: 0 for the grid fields; 1 voxel for the
  /// Delaunay field, whose triangulation holds a sample of the particles' surface voxels.
  virtual float slack() const { return 0; }
  /// The spots bestFit picks from with the values it ranks them by, for a field that keeps
  /// candidates apart from its voxels (Delaunay: rounded circumcentres, valued by their circumradius
  /// less the rounding and the jitter of its vertices). Empty for the grid fields, whose every free
  /// voxel is a candidate valued at().
  virtual std::vector<std::pair<Voxel, float>> candidates() const { return {}; }
};

/// The field of the given kind over an empty volume, walled or periodic.
std::unique_ptr<SpaciousnessField> makeSpaciousnessField(PlacerKind kind, Dims dims, float maxRadius,
                                                         bool periodic = false);

}  // namespace solidtex
