#include "io/writeNpy.h"

#include <cstdint>

#include "common/writeFileBytes.h"

namespace solidtex {

std::string npyHeader(const std::string& descr, const std::vector<std::size_t>& shape) {
  std::string dict = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': (";
  for (std::size_t axis = 0; axis < shape.size(); ++axis)
    dict += (axis > 0 ? ", " : "") + std::to_string(shape[axis]);
  dict += shape.size() == 1 ? ",), }" : "), }";  // numpy's own: (4,) and (2, 3)
  constexpr std::size_t kPrefix = 10;            // magic (6), version (2), header length (2)
  const std::size_t total = (kPrefix + dict.size() + 1 + 63) / 64 * 64;
  dict.append(total - kPrefix - dict.size() - 1, ' ');
  dict += '\n';
  const auto length = std::uint16_t(dict.size());
  std::string header("\x93NUMPY\x01\x00", 8);
  header += char(length & 0xff);
  header += char(length >> 8);
  return header + dict;
}

void writeNpy(const std::string& path, const std::string& descr, const std::vector<std::size_t>& shape,
              const void* data, std::size_t elementSize) {
  std::size_t count = 1;
  for (std::size_t n : shape) count *= n;
  const std::string header = npyHeader(descr, shape);
  writeFileBytes(path, {{header.data(), header.size()}, {data, count * elementSize}});
}

}  // namespace solidtex
