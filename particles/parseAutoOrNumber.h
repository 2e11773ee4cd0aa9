#pragma once
/// @file
/// Reading an option that is "auto" (fitted) or a number in a range.

#include <optional>
#include <string>

namespace solidtex {

/// "auto" gives none; a number in [lo, hi] that is the whole text gives itself; anything else throws
/// OptionError naming `option`.
std::optional<double> parseAutoOrNumber(const std::string& text, const std::string& option, double lo,
                                        double hi);

}  // namespace solidtex
