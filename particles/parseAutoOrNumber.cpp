#include "particles/parseAutoOrNumber.h"

#include <sstream>

#include "common/Error.h"

namespace solidtex {

std::optional<double> parseAutoOrNumber(const std::string& text, const std::string& option, double lo,
                                        double hi) {
  if (text == "auto") return std::nullopt;
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == text.size() && used > 0 && value >= lo && value <= hi) return value;
  std::ostringstream message;
  message << option << " must be auto or a number from " << lo << " to " << hi << ", got '" << text << "'";
  throw OptionError(message.str());
}

}  // namespace solidtex
