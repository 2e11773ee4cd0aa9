#include "python/keywords.h"

namespace py = pybind11;

namespace solidtex::python {

std::optional<std::string> asPath(const py::handle& value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::hasattr(value, "__fspath__")) {
    const py::object path = value.attr("__fspath__")();
    if (py::isinstance<py::str>(path)) return path.cast<std::string>();
  }
  return std::nullopt;
}

Keywords::Keywords(std::string function, const py::kwargs& kwargs)
    : function_(std::move(function)), remaining_(py::dict(kwargs)) {}

py::object Keywords::take(const char* name) {
  if (!remaining_.contains(name)) return py::none();
  py::object value = remaining_[name];
  PyDict_DelItemString(remaining_.ptr(), name);
  return value;
}

void Keywords::wrongType(const char* name, const char* wanted, const py::handle& value) const {
  const std::string given = py::str(py::type::handle_of(value).attr("__name__"));
  throw py::type_error(function_ + "(): " + name + " must be " + wanted + ", not " + given);
}

std::optional<long long> Keywords::integer(const char* name) {
  const py::object value = take(name);
  if (value.is_none()) return std::nullopt;
  if (py::isinstance<py::bool_>(value) || !py::isinstance<py::int_>(value)) wrongType(name, "an int", value);
  return value.cast<long long>();
}

std::optional<double> Keywords::number(const char* name) {
  const py::object value = take(name);
  if (value.is_none()) return std::nullopt;
  if (py::isinstance<py::bool_>(value) ||
      !(py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)))
    wrongType(name, "a number", value);
  return value.cast<double>();
}

std::optional<bool> Keywords::flag(const char* name) {
  const py::object value = take(name);
  if (value.is_none()) return std::nullopt;
  if (!py::isinstance<py::bool_>(value)) wrongType(name, "True or False", value);
  return value.cast<bool>();
}

std::optional<std::string> Keywords::text(const char* name) {
  const py::object value = take(name);
  if (value.is_none()) return std::nullopt;
  if (!py::isinstance<py::str>(value)) wrongType(name, "a str", value);
  return value.cast<std::string>();
}

std::optional<std::string> Keywords::path(const char* name) {
  const py::object value = take(name);
  if (value.is_none()) return std::nullopt;
  std::optional<std::string> path = asPath(value);
  if (!path) wrongType(name, "a path (str or os.PathLike)", value);
  return path;
}

std::optional<std::vector<int>> Keywords::integers(const char* name, std::size_t count) {
  const py::object value = take(name);
  if (value.is_none()) return std::nullopt;
  const std::string wanted =
      count > 0 ? "a sequence of " + std::to_string(count) + " ints" : "a sequence of ints";
  if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) ||
      (count > 0 ? py::len(value) != count : py::len(value) == 0))
    wrongType(name, wanted.c_str(), value);
  std::vector<int> result;
  for (const py::handle item : value) {
    if (py::isinstance<py::bool_>(item) || !py::isinstance<py::int_>(item))
      wrongType(name, wanted.c_str(), value);
    result.push_back(item.cast<int>());
  }
  return result;
}

void Keywords::finish() const {
  if (remaining_.empty()) return;
  const std::string name = py::str(remaining_.begin()->first);
  throw py::type_error(function_ + "() got an unexpected keyword argument '" + name + "'");
}

}  // namespace solidtex::python
