#pragma once
// Internal: one factory per field kind, each defined in its own translation unit.
#include <memory>

#include "placement/SpaciousnessField.h"

namespace solidtex::detail {

std::unique_ptr<SpaciousnessField> makeDiscreteVoronoiField(Dims dims, float maxRadius, bool periodic);
std::unique_ptr<SpaciousnessField> makeBruteForceField(Dims dims, float maxRadius, bool periodic);
std::unique_ptr<SpaciousnessField> makeEdtField(Dims dims, float maxRadius, bool periodic);
std::unique_ptr<SpaciousnessField> makeDelaunayField(Dims dims, float maxRadius, bool periodic);

}  // namespace solidtex::detail
