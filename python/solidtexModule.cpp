// The Python module. particles() and analyze() call the library (a numpy image or a path in, numpy
// arrays and the report out, no file unless asked for); synthesize() and compare() still run the
// command of the same name through the command line's parser and job and read back what it wrote.

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
#include <regex>
#include <string>
#include <vector>

#include "cli/application.h"
#include "cli/commandLine.h"
#include "common/Error.h"
#include "common/OutputFiles.h"
#include "common/ThreadLimit.h"
#include "common/interruption.h"
#include "common/memoryBudget.h"
#include "particleSolid/makeParticleSolid.h"
#include "particleSolid/particleSolidReport.h"
#include "pipeline/jobSupport.h"
#include "python/keywords.h"
#include "segmentation/drawLabels.h"
#include "segmentation/imageIO.h"
#include "segmentation/reportJson.h"
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

/// Raised from a progress report when Python has a signal to handle (Ctrl-C): the work unwinds and
/// the pending KeyboardInterrupt is raised in its place.
struct Interrupted {};

/// Python's signals (Ctrl-C), looked at between units of the library's work.
void checkSignals() {
  const py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw Interrupted{};
}

/// A library message names options as the command line spells them (--min-area); Python's
/// keywords are min_area.
std::string asKeywords(std::string message) {
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

/// A photo given as a path (read as the command line reads it) or as a numpy array (H, W), (H, W, 3)
/// or (H, W, 4), uint8 or float in [0, 1] (sRGB). `name` labels it in reports.
cv::Mat photoOf(const py::handle& photo, std::string& name) {
  if (const std::optional<std::string> path = asPath(photo)) {
    name = *path;
    cv::Mat image;
    runReleased([&] { image = loadPhoto(*path); });
    return image;
  }
  if (!py::isinstance<py::array>(photo))
    throw py::type_error("photo must be a path (str or os.PathLike) or a numpy array, not " +
                         std::string(py::str(py::type::handle_of(photo).attr("__name__"))));
  name = "array";
  const auto array = py::reinterpret_borrow<py::array>(photo);
  if (array.ndim() != 2 && array.ndim() != 3)
    throw py::value_error("photo must have the shape (height, width) or (height, width, channels)");
  const int channels = array.ndim() == 2 ? 1 : int(array.shape(2));
  const bool bytes = array.dtype().is(py::dtype::of<std::uint8_t>());
  if (!bytes && array.dtype().kind() != 'f') throw py::value_error("photo must be uint8, or float in [0, 1]");
  const py::array pixels =
      bytes ? py::array(py::array_t<std::uint8_t, py::array::c_style>::ensure(array))
            : py::array(py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array));
  cv::Mat image;
  runReleased([&] {
    image = photoFromPixels(pixels.data(), bytes ? PixelType::UInt8 : PixelType::Float32, int(array.shape(1)),
                            int(array.shape(0)), channels, name);
  });
  return image;
}

/// A numpy array that owns `values` (moved, not copied), shaped `shape`.
template <typename T>
py::array_t<T> ownedArray(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  const py::capsule free(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, owned->data(), free);
}

py::object toPython(const nlohmann::json& json) {
  return py::module_::import("json").attr("loads")(json.dump());
}

SegmentationOptions segmentationOptions(Keywords& keywords) {
  SegmentationOptions options;
  options.maskPath = keywords.path("mask");
  options.invert = keywords.flag("invert").value_or(false);
  options.split = keywords.flag("split").value_or(true);
  options.minArea = keywords.number("min_area").value_or(-1);
  return options;
}

ParticleSolidOptions particleSolidOptions(Keywords& keywords) {
  ParticleSolidOptions options;
  options.segmentation = segmentationOptions(keywords);
  const int size = int(keywords.integer("size").value_or(128));
  options.dims = {size, size, size};
  if (const auto dims = keywords.integers("dims", 3)) options.dims = {(*dims)[0], (*dims)[1], (*dims)[2]};
  options.voxelsPerPixel = keywords.number("scale").value_or(0);
  options.placer = parsePlacerKind(keywords.text("placer").value_or("edt"));
  options.sizing = parseSizing(keywords.text("sizing").value_or("sections"));
  options.arrangement = parseArrangement(keywords.text("arrangement").value_or("uniform"));
  options.boundary = parseBoundary(keywords.text("boundary").value_or("open"));
  options.matrix = parseTexture("matrix", keywords.text("matrix").value_or("synthesized"));
  options.particleTexture =
      parseTexture("particle_texture", keywords.text("particle_texture").value_or("projected"));
  options.particles.views = int(keywords.integer("views").value_or(options.particles.views));
  options.particles.shapes = int(keywords.integer("shapes").value_or(options.particles.shapes));
  options.smoothing = keywords.number("smoothing");
  options.seed = std::uint64_t(keywords.integer("seed").value_or(1));
  return options;
}

/// particles(photo, **options): the solid's arrays and report; a .vdb and a report file only when
/// output= and report= are given.
py::dict particles(const py::object& photo, const py::kwargs& kwargs) {
  Keywords keywords("particles", kwargs);
  ParticleSolidOptions options;
  runParsing([&] { options = particleSolidOptions(keywords); });
  const int threads = int(keywords.integer("threads").value_or(0));
  const std::optional<std::string> output = keywords.path("output"), reportPath = keywords.path("report");
  const bool progress = keywords.flag("progress").value_or(false);
  keywords.finish();
  std::string name;
  const cv::Mat image = photoOf(photo, name);
  ParticleSolid solid;
  nlohmann::json report;
  runReleased([&] {
    const ThreadLimit limit(threads);
    ProgressLine line(progress);
    std::optional<OutputFiles> outputs;
    if (output || reportPath) {
      outputs.emplace();
      if (name != "array") outputs->addInput(name);
      if (output) outputs->addFile("output", *output, {".vdb"});
      if (reportPath) outputs->addFile("report", *reportPath, {".json"});
    }
    solid = makeParticleSolid(image, name, options, [&line](const std::string& step, double fraction) {
      line.update(step, fraction);
      checkInterruption();
    });
    line.done();
    report = particleSolidReport(solid, options);
    report["time_seconds"] = solid.timer.finish();
    report["peak_memory_mib"] = peakMemoryMiB();
    if (!outputs) return;
    solid.volume.metadata = particleSolidMetadata(solid, options, "solidtex.particles (Python)");
    if (output) outputs->write(*output, [&](const std::string& path) { writeVdb(path, solid.volume); });
    if (reportPath)
      outputs->write(*reportPath, [&](const std::string& path) { writeJsonFile(path, report); });
    outputs->commit();
  });
  const Dims d = solid.volume.dims;
  std::vector<float> rgb(solid.volume.color.size() * 3);
  for (std::size_t i = 0; i < solid.volume.color.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c) rgb[3 * i + c] = solid.volume.color[i][c];
  solid.volume.color = {};
  py::dict result;
  result["particle_id"] = ownedArray(std::move(solid.volume.particleId), {d.z, d.y, d.x});
  result["color"] = ownedArray(std::move(rgb), {d.z, d.y, d.x, 3});
  result["report"] = toPython(report);
  return result;
}

/// analyze(photo, **options): the photo's particle statistics as a dict; the outlined photo as
/// labels= (a PNG) when asked.
py::object analyze(const py::object& photo, const py::kwargs& kwargs) {
  Keywords keywords("analyze", kwargs);
  const SegmentationOptions options = segmentationOptions(keywords);
  const std::optional<std::string> labels = keywords.path("labels"), reportPath = keywords.path("report");
  keywords.finish();
  std::string name;
  const cv::Mat image = photoOf(photo, name);
  nlohmann::json report;
  runReleased([&] {
    std::optional<OutputFiles> outputs;
    if (labels || reportPath) {
      outputs.emplace();
      if (name != "array") outputs->addInput(name);
      if (labels) outputs->addFile("labels", *labels, {".png"});
      if (reportPath) outputs->addFile("report", *reportPath, {".json"});
    }
    const ExemplarStats stats = analyzeExemplar(image, name, options);
    report = toJson(stats);
    if (!outputs) return;
    if (labels)
      outputs->write(*labels, [&](const std::string& path) { writeImage(path, drawLabels(image, stats)); });
    if (reportPath)
      outputs->write(*reportPath, [&](const std::string& path) { writeJsonFile(path, report); });
    outputs->commit();
  });
  return toPython(report);
}

}  // namespace
}  // namespace solidtex::python

PYBIND11_MODULE(solidtex, m) {
  using namespace solidtex::python;
  m.doc() =
      "solidtex: one photo of a material in, a 3D solid texture out. particles and analyze take a "
      "numpy image or a path and return arrays and dicts; synthesize and compare run the command "
      "of the same name with the same options (size=64 is --size 64) and return what it wrote.";
  errorType = new py::object(py::exception<std::runtime_error>(m, "Error", PyExc_RuntimeError));
  m.def("analyze", &analyze, py::arg("photo"),
        "Segments a photo of particles (a path, or a numpy array: (H, W), (H, W, 3) or (H, W, 4), uint8 "
        "or float sRGB in [0, 1]): its statistics (particles, area fraction, area histogram) as a dict. "
        "Keywords: mask (a path), invert, split, min_area; labels and report write the outlined photo "
        "(PNG) and the statistics (JSON).");
  m.def("particles", &particles, py::arg("photo"),
        "Makes a particle solid from a photo (a path or a numpy array, as analyze takes): a dict of numpy "
        "arrays particle_id (Z, Y, X int32, 0 = matrix), color (Z, Y, X, 3 float32, linear RGB) and the "
        "report (a dict). Keywords as the command line's options: size, dims, scale, placer, sizing, "
        "arrangement, boundary, matrix, particle_texture, views, shapes, smoothing, seed, threads, mask, "
        "invert, split, min_area; output (.vdb) and report (.json) write files; progress shows the "
        "progress line. Ctrl-C stops it and leaves no file.");
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
