// The Python module: each function runs the command of the same name through the command line's
// own parser and job, so options, checks, messages and the .vdb's bytes are the CLI's, and hands
// back what the command wrote (the report as a dict, the volume as numpy arrays).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <mutex>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "cli/application.h"
#include "cli/commandLine.h"
#include "common/Error.h"
#include "voxel/vdbIO.h"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace solidtex::python {
namespace {

/// A failure that the command line reports with exit code 1 (bad input, an unwritable output, too
/// little memory); a wrong command line raises ValueError, as it exits with 2. Never destroyed: the
/// interpreter may be gone by then.
py::object* errorType = nullptr;

/// A command owns process-wide state while it runs (one OutputFiles, stdout, stderr's descriptor,
/// the address-space cap): Python threads take turns.
std::mutex commandMutex;

/// Keyword arguments as options: size=64 is --size 64, no_split=True is --no-split, dims=(64, 64,
/// 32) is --dims 64 64 32; None and False leave an option out.
std::vector<std::string> optionsOf(const py::kwargs& kwargs) {
  std::vector<std::string> options;
  for (const auto& [key, value] : kwargs) {
    std::string name = "--" + py::cast<std::string>(key);
    for (char& c : name) c = c == '_' ? '-' : c;
    if (value.is_none() || (py::isinstance<py::bool_>(value) && !py::cast<bool>(value))) continue;
    options.push_back(name);
    if (py::isinstance<py::bool_>(value)) continue;
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
      for (const auto& item : value) options.push_back(py::str(item));
    } else {
      options.push_back(py::str(value));
    }
  }
  return options;
}

/// The command's stdout summary line is for a terminal, not for a library call.
class SilentStdout {
public:
  SilentStdout() : saved_(std::cout.rdbuf(nullptr)) {}
  ~SilentStdout() {
    std::cout.rdbuf(saved_);
    std::cout.clear();
  }

private:
  std::streambuf* saved_;
};

/// Runs `solidtex ARGUMENTS` in this process: ValueError for a wrong command line, solidtex.Error
/// for a failed command, MemoryError when memory ran out; the messages are the command line's.
void runCommand(const std::vector<std::string>& arguments) {
  std::optional<std::string> usage, failure;
  bool outOfMemory = false;
  {
    py::gil_scoped_release released;
    const std::lock_guard<std::mutex> oneAtATime(commandMutex);
    const auto application = cli::makeApplication(cli::volumeCommandLine(arguments));
    CLI::App& app = application->app;
    std::vector<std::string> argv{"solidtex"};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    std::vector<char*> pointers;
    for (std::string& argument : argv) pointers.push_back(argument.data());
    try {
      app.parse(int(pointers.size()), pointers.data());
      const SilentStdout silent;
      application->actions.at(app.get_subcommands().front()->get_name())();
    } catch (const CLI::ParseError& e) {
      usage = cli::usageMessage(app, e.what());
    } catch (const OptionError& e) {
      usage = cli::usageMessage(app, e.what());
    } catch (const std::bad_alloc&) {
      outOfMemory = true;
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  if (usage) throw py::value_error(*usage);
  if (outOfMemory) throw std::bad_alloc();  // pybind11 raises MemoryError
  if (failure) {
    PyErr_SetString(errorType->ptr(), failure->c_str());
    throw py::error_already_set();
  }
}

/// A folder for what the caller did not ask to keep, removed with it.
class ScratchFolder {
public:
  ScratchFolder() {
    std::string pattern = (fs::temp_directory_path() / "solidtex-python-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary folder");
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
  fs::path path_;
};

py::object readJson(const std::string& path) {
  std::ifstream in(path);
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  return py::module_::import("json").attr("loads")(text);
}

/// `option`'s value among the keyword arguments, or a file of `scratch` that is then passed as it.
std::string outputPath(py::kwargs& kwargs, const char* option, const ScratchFolder& scratch,
                       const std::string& name) {
  if (kwargs.contains(option) && !kwargs[option].is_none()) return py::str(kwargs[option]);
  kwargs[option] = scratch.file(name);
  return scratch.file(name);
}

/// Progress lines stay off unless quiet=False is given.
void quietUnlessAsked(py::kwargs& kwargs) {
  if (!kwargs.contains("quiet")) kwargs["quiet"] = true;
}

template <typename T>
py::array_t<T> arrayOf(const std::vector<T>& values, std::vector<py::ssize_t> shape) {
  py::array_t<T> array(shape);
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

/// The volume's grids as (Z, Y, X[, 3]) arrays, x fastest as in the .vdb's dense form.
py::dict volumeArrays(const std::string& path) {
  const SolidVolume volume = readVdb(path);
  const Dims& d = volume.dims;
  const std::vector<py::ssize_t> zyx{d.z, d.y, d.x};
  py::dict arrays;
  if (!volume.color.empty()) {
    std::vector<float> rgb(volume.color.size() * 3);
    for (std::size_t i = 0; i < volume.color.size(); ++i)
      for (int c = 0; c < 3; ++c) rgb[3 * i + c] = volume.color[i][c];
    arrays["color"] = arrayOf(rgb, {d.z, d.y, d.x, 3});
  }
  if (!volume.particleId.empty()) arrays["particle_id"] = arrayOf(volume.particleId, zyx);
  if (!volume.density.empty()) arrays["density"] = arrayOf(volume.density, zyx);
  return arrays;
}

/// `solidtex COMMAND INPUTS -o OUT --report R ...`: the report and the volume's arrays.
py::dict runVolumeCommand(const std::string& command, const std::vector<std::string>& inputs,
                          const std::optional<std::string>& output, py::kwargs kwargs) {
  const ScratchFolder scratch;
  const std::string vdb = output.value_or(scratch.file("volume.vdb"));
  const std::string report = outputPath(kwargs, "report", scratch, "report.json");
  quietUnlessAsked(kwargs);
  std::vector<std::string> arguments{command};
  arguments.insert(arguments.end(), inputs.begin(), inputs.end());
  arguments.insert(arguments.end(), {"-o", vdb});
  const auto options = optionsOf(kwargs);
  arguments.insert(arguments.end(), options.begin(), options.end());
  runCommand(arguments);
  py::dict result = volumeArrays(vdb);
  result["report"] = readJson(report);
  return result;
}

/// `solidtex COMMAND INPUTS --report R ...`: the report.
py::object runReportCommand(const std::string& command, const std::vector<std::string>& inputs,
                            py::kwargs kwargs) {
  const ScratchFolder scratch;
  const std::string report = outputPath(kwargs, "report", scratch, "report.json");
  std::vector<std::string> arguments{command};
  arguments.insert(arguments.end(), inputs.begin(), inputs.end());
  const auto options = optionsOf(kwargs);
  arguments.insert(arguments.end(), options.begin(), options.end());
  runCommand(arguments);
  return readJson(report);
}

}  // namespace
}  // namespace solidtex::python

PYBIND11_MODULE(solidtex, m) {
  using namespace solidtex::python;
  m.doc() =
      "solidtex: one photo of a material in, a 3D solid texture out. Each function runs the "
      "command of the same name with the same options (size=64 is --size 64, no_split=True "
      "is --no-split) and returns what it wrote.";
  errorType = new py::object(py::exception<std::runtime_error>(m, "Error", PyExc_RuntimeError));
  m.def(
      "analyze",
      [](const std::string& photo, py::kwargs kwargs) {
        return runReportCommand("analyze", {photo}, kwargs);
      },
      py::arg("photo"),
      "Segments a photo of particles: its report (particles, area fraction, area histogram) as a dict.");
  m.def(
      "particles",
      [](const std::string& photo, std::optional<std::string> output, py::kwargs kwargs) {
        return runVolumeCommand("particles", {photo}, output, kwargs);
      },
      py::arg("photo"), py::arg("output") = py::none(),
      "Makes a particle solid: a dict of numpy arrays color (Z,Y,X,3 linear RGB), particle_id (Z,Y,X) "
      "and report (a dict). output: also keep the .vdb there, byte for byte the CLI's.");
  m.def(
      "synthesize",
      [](const std::string& exemplar, std::optional<std::string> output, py::kwargs kwargs) {
        return runVolumeCommand("synthesize", {exemplar}, output, kwargs);
      },
      py::arg("exemplar"), py::arg("output") = py::none(),
      "Synthesises a continuous solid from a photo or a .vdb exemplar: a dict of numpy arrays (color, "
      "density when the exemplar has one) and report.");
  m.def(
      "compare",
      [](const std::string& photo, const std::string& volume, py::kwargs kwargs) {
        return runReportCommand("compare", {photo, volume}, kwargs);
      },
      py::arg("photo"), py::arg("volume"), "Compares a solid with its photo: the report as a dict.");
}
