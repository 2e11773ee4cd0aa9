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

/// An option's value out of its range or contradicting another option: the command line is wrong
/// (exit code 2), as for options the parser itself refuses.
class OptionError : public InputError {
public:
  explicit OptionError(const std::string& what) : InputError(what) {}
};

}  // namespace solidtex
