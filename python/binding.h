#pragma once
// What the module's functions share: how a library call runs and raises, and numpy arrays that own
// the library's vectors.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <mutex>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/Error.h"
#include "common/interruption.h"

namespace solidtex::python {

namespace py = pybind11;

/// solidtex.Error: input the library cannot use (a photo it cannot read, an unwritable output, too
/// little memory); options out of range raise ValueError. Never destroyed: the interpreter may be
/// gone by then.
inline py::object* errorType = nullptr;

/// A call owns process-wide state while it runs (one OutputFiles, the thread limit, stderr's
/// descriptor while libraries print): Python threads take turns.
inline std::mutex commandMutex;

/// Raised from a progress report when Python has a signal to handle (Ctrl-C): the work unwinds and
/// the pending KeyboardInterrupt is raised in its place.
struct Interrupted {};

/// Python's signals (Ctrl-C), looked at between units of the library's work.
inline void checkSignals() {
  const py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw Interrupted{};
}

/// A library message names options as the command line spells them (--min-area); Python's
/// keywords are min_area.
inline std::string asKeywords(std::string message) {
  static const std::regex flag("--([a-z]+(-[a-z]+)*)");
  std::string result;
  std::sregex_iterator it(message.begin(), message.end(), flag), end;
  std::size_t from = 0;
  for (; it != end; ++it) {
    std::string name = (*it)[1].str();
    std::replace(name.begin(), name.end(), '-', '_');
    result += message.substr(from, std::size_t(it->position()) - from) + name;
    from = std::size_t(it->position() + it->length());
  }
  return result + message.substr(from);
}

/// Runs `work` with the GIL released, one library call at a time (OutputFiles and the thread limit
/// are process-wide), and raises what it threw as Python does: ValueError for options out of
/// range, solidtex.Error for input it cannot use, MemoryError, KeyboardInterrupt.
template <typename Work>
void runReleased(Work&& work) {
  std::optional<std::string> usage, failure;
  bool outOfMemory = false, interrupted = false;
  {
    py::gil_scoped_release released;
    const std::lock_guard<std::mutex> oneAtATime(commandMutex);
    const InterruptionCheck interruptible(checkSignals);
    try {
      work();
    } catch (const Interrupted&) {
      interrupted = true;
    } catch (const OptionError& e) {
      usage = asKeywords(e.what());
    } catch (const std::bad_alloc&) {
      outOfMemory = true;
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  if (interrupted) throw py::error_already_set();
  if (usage) throw py::value_error(*usage);
  if (outOfMemory) throw std::bad_alloc();
  if (failure) {
    PyErr_SetString(errorType->ptr(), failure->c_str());
    throw py::error_already_set();
  }
}

/// Reads keyword values into options: a value the library refuses (an unknown placer) is a
/// ValueError naming the keyword.
template <typename Parse>
void runParsing(Parse&& parse) {
  try {
    parse();
  } catch (const py::builtin_exception&) {
    throw;
  } catch (const InputError& e) {
    throw py::value_error(asKeywords(e.what()));
  }
}

/// A numpy array that owns `values` (moved, not copied), shaped `shape`.
template <typename T>
py::array_t<T> ownedArray(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  const py::capsule free(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, owned->data(), free);
}

inline py::object toPython(const nlohmann::json& json) {
  return py::module_::import("json").attr("loads")(json.dump());
}

}  // namespace solidtex::python
