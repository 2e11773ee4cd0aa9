#include "placement/SpaciousnessField.h"

#include "common/Error.h"
#include "placement/detail/fieldFactories.h"
#include "placement/detail/voxelSets.h"

namespace solidtex {

PlacerKind parsePlacerKind(const std::string& name) {
  for (PlacerKind kind : {PlacerKind::Discrete, PlacerKind::Brute, PlacerKind::Edt, PlacerKind::Delaunay})
    if (name == placerName(kind)) return kind;
  throw OptionError("unknown placer '" + name + "': expected discrete, brute, edt or delaunay");
}

const char* placerName(PlacerKind kind) {
  switch (kind) {
    case PlacerKind::Discrete:
      return "discrete";
    case PlacerKind::Brute:
      return "brute";
    case PlacerKind::Edt:
      return "edt";
    case PlacerKind::Delaunay:
      return "delaunay";
  }
  return "unknown";
}

std::unique_ptr<SpaciousnessField> makeSpaciousnessField(PlacerKind kind, Dims dims, float maxRadius,
                                                         bool periodic) {
  detail::checkFieldArguments(dims, maxRadius);
  switch (kind) {
    case PlacerKind::Discrete:
      return detail::makeDiscreteVoronoiField(dims, maxRadius, periodic);
    case PlacerKind::Brute:
      return detail::makeBruteForceField(dims, maxRadius, periodic);
    case PlacerKind::Edt:
      return detail::makeEdtField(dims, maxRadius, periodic);
    case PlacerKind::Delaunay:
      return detail::makeDelaunayField(dims, maxRadius, periodic);
  }
  throw OptionError("unknown placer kind");
}

}  // namespace solidtex
