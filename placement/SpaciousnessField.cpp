#include "placement/SpaciousnessField.h"

#include <iterator>

#include "common/Error.h"
#include "placement/detail/voxelSets.h"

namespace solidtex {

// Each field's factory is defined in its own translation unit (placement/<Name>Field.cpp).
namespace placement::detail {
std::unique_ptr<SpaciousnessField> makeDiscreteVoronoiField(Dims dims, float maxRadius, bool periodic);
std::unique_ptr<SpaciousnessField> makeBruteForceField(Dims dims, float maxRadius, bool periodic);
std::unique_ptr<SpaciousnessField> makeEdtField(Dims dims, float maxRadius, bool periodic);
std::unique_ptr<SpaciousnessField> makeDelaunayField(Dims dims, float maxRadius, bool periodic);
}  // namespace placement::detail

namespace {

using FieldFactory = std::unique_ptr<SpaciousnessField> (*)(Dims dims, float maxRadius, bool periodic);

struct PlacerRow {
  PlacerKind kind;
  const char* name;
  FieldFactory make;
};

const PlacerRow kPlacers[] = {
    {PlacerKind::Discrete, "discrete", placement::detail::makeDiscreteVoronoiField},
    {PlacerKind::Brute, "brute", placement::detail::makeBruteForceField},
    {PlacerKind::Edt, "edt", placement::detail::makeEdtField},
    {PlacerKind::Delaunay, "delaunay", placement::detail::makeDelaunayField},
};

const PlacerRow& rowOf(PlacerKind kind) {
  for (const PlacerRow& row : kPlacers)
    if (row.kind == kind) return row;
  throw OptionError("unknown placer kind");
}

}  // namespace

const std::vector<PlacerKind>& placerKinds() {
  static const std::vector<PlacerKind> kinds = [] {
    std::vector<PlacerKind> all;
    for (const PlacerRow& row : kPlacers) all.push_back(row.kind);
    return all;
  }();
  return kinds;
}

PlacerKind parsePlacerKind(const std::string& name) {
  for (const PlacerRow& row : kPlacers)
    if (name == row.name) return row.kind;
  throw OptionError("unknown placer '" + name + "': expected " + placerNames());
}

const char* placerName(PlacerKind kind) { return rowOf(kind).name; }

std::string placerNames() {
  std::string names;
  const std::size_t count = std::size(kPlacers);
  for (std::size_t i = 0; i < count; ++i)
    names += (i == 0 ? "" : i + 1 == count ? " or " : ", ") + std::string(kPlacers[i].name);
  return names;
}

std::unique_ptr<SpaciousnessField> makeSpaciousnessField(PlacerKind kind, Dims dims, float maxRadius,
                                                         bool periodic) {
  placement::detail::checkFieldArguments(dims, maxRadius);
  return rowOf(kind).make(dims, maxRadius, periodic);
}

}  // namespace solidtex
