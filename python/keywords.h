#pragma once
// Keyword arguments read one by one with their types checked, so that a wrong one raises
// TypeError naming it ("particles(): size must be an int, not str"), and an unknown one is caught.
#include <pybind11/pybind11.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace solidtex::python {

class Keywords {
public:
  Keywords(std::string function, const pybind11::kwargs& kwargs);

  std::optional<long long> integer(const char* name);
  std::optional<double> number(const char* name);
  std::optional<bool> flag(const char* name);
  std::optional<std::string> text(const char* name);
  /// A str or an os.PathLike.
  std::optional<std::string> path(const char* name);
  /// A sequence of `count` ints (0: of any length but empty).
  std::optional<std::vector<int>> integers(const char* name, std::size_t count = 0);

  /// Removes `name` and returns its value (None when absent), for a keyword read another way.
  pybind11::object take(const char* name);

  /// TypeError for a keyword none of the above asked for.
  void finish() const;

  /// "particles(): size must be an int, not str" as TypeError.
  [[noreturn]] void wrongType(const char* name, const char* wanted, const pybind11::handle& value) const;

private:
  std::string function_;
  pybind11::dict remaining_;
};

/// A str or os.PathLike as a path; nullopt for anything else.
std::optional<std::string> asPath(const pybind11::handle& value);

}  // namespace solidtex::python
