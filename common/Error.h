#pragma once
#include <stdexcept>
#include <string>

namespace solidtex {

/// Bad input from the user (a missing file, an absurd size, an invalid option):
/// the command line prints what() as one line and exits non-zero.
class InputError : public std::runtime_error {
public:
  explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace solidtex
