#include "placement/detail/BucketField.h"

namespace solidtex::placement::detail {

std::vector<float> squaredDistanceValues(float maxRadius) {
  const auto capKey = std::uint64_t(std::ceil(double(maxRadius) * double(maxRadius)));
  std::vector<float> values(capKey + 1);
  for (std::uint64_t k = 0; k < capKey; ++k) values[k] = float(std::sqrt(double(k)));
  values[capKey] = maxRadius;
  return values;
}

}  // namespace solidtex::placement::detail
