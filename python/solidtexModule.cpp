// The Python module: each function calls the library behind the command of the same name, with a
// numpy array or a path in and numpy arrays and the report out; no file is written unless asked for.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <filesystem>
#include <mutex>
#include <new>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "Version.h"
#include "common/Error.h"
#include "common/OutputFiles.h"
#include "common/ProgressLine.h"
#include "common/ThreadLimit.h"
#include "common/interruption.h"
#include "common/memoryBudget.h"
#include "io/frameFieldIO.h"
#include "io/imageIO.h"
#include "io/vdbIO.h"
#include "particleSolid/makeParticleSolid.h"
#include "particleSolid/particleSolidReport.h"
#include "pipeline/compareJob.h"
#include "pipeline/growSolidJob.h"
#include "pipeline/jobOutputs.h"
#include "pipeline/planePixelSizes.h"
#include "pipeline/synthesizeJob.h"
#include "pipeline/synthesizeVolumeJob.h"
#include "python/binding.h"
#include "python/keywords.h"
#include "python/materialsBindings.h"
#include "segmentation/analyzeExemplar.h"
#include "segmentation/drawLabels.h"
#include "segmentation/reportJson.h"
#include "synthesis/FrameField.h"
#include "synthesis/synthesizeFromVolume.h"
#include "synthesis/synthesizeSolid.h"
#include "validation/continuousQuality.h"

namespace py = pybind11;

namespace solidtex::python {
namespace {

/// A photo given as a path (read as the command line reads it) or as a numpy array (H, W), (H, W, 3)
/// or (H, W, 4), uint8 or float in [0, 1] (sRGB). `name` labels it in reports; `what` names it in errors.
cv::Mat photoOf(const py::handle& photo, std::string& name, const std::string& what = "photo") {
  if (const std::optional<std::string> path = asPath(photo)) {
    name = *path;
    cv::Mat image;
    runReleased([&] { image = loadPhoto(*path); });
    return image;
  }
  if (!py::isinstance<py::array>(photo))
    throw py::type_error(what + " must be a path (str or os.PathLike) or a numpy array, not " +
                         std::string(py::str(py::type::handle_of(photo).attr("__name__"))));
  name = "array";
  const auto array = py::reinterpret_borrow<py::array>(photo);
  if (array.ndim() != 2 && array.ndim() != 3)
    throw py::value_error(what + " must have the shape (height, width) or (height, width, channels)");
  const int channels = array.ndim() == 2 ? 1 : int(array.shape(2));
  const bool bytes = array.dtype().is(py::dtype::of<std::uint8_t>());
  if (!bytes && array.dtype().kind() != 'f')
    throw py::value_error(what + " must be uint8, or float in [0, 1]");
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

/// Colours as one float array, three values per voxel.
std::vector<float> interleaved(std::vector<Rgb>&& colors) {
  std::vector<float> rgb(colors.size() * 3);
  for (std::size_t i = 0; i < colors.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c) rgb[3 * i + c] = colors[i][c];
  colors = {};
  return rgb;
}

/// The seed keyword: a non-negative int, 1 when not given.
std::uint64_t seedOf(Keywords& keywords) {
  const long long seed = keywords.integer("seed").value_or(1);
  if (seed < 0) throw py::value_error("seed must not be negative");
  return std::uint64_t(seed);
}

/// The mask keyword: a path (read as --mask reads it), a bool array (True = particle) or an image
/// array as photos are given (white = particle).
void readMask(Keywords& keywords, SegmentationOptions& options) {
  const py::object mask = keywords.take("mask");
  if (mask.is_none()) return;
  if (const std::optional<std::string> path = asPath(mask)) {
    options.maskPath = path;
    return;
  }
  if (!py::isinstance<py::array>(mask)) keywords.wrongType("mask", "a path or a numpy array", mask);
  const auto array = py::reinterpret_borrow<py::array>(mask);
  if (array.dtype().kind() == 'b') {
    if (array.ndim() != 2) throw py::value_error("mask must have the shape (height, width)");
    const auto values = py::array_t<bool, py::array::c_style>::ensure(array);
    options.mask =
        cv::Mat(int(array.shape(0)), int(array.shape(1)), CV_8U, const_cast<bool*>(values.data())) != 0;
    return;
  }
  std::string name;
  const cv::Mat image = photoOf(mask, name, "mask");
  options.mask = maskFromImage(image);
}

SegmentationOptions segmentationOptions(Keywords& keywords) {
  SegmentationOptions options;
  readMask(keywords, options);
  options.invert = keywords.flag("invert").value_or(false);
  options.split = keywords.flag("split").value_or(true);
  options.outlines = parseOutlineMethod(keywords.text("outlines").value_or("auto"));
  options.minArea = keywords.number("min_area").value_or(-1);
  return options;
}

/// phases= (an int from 1 to 8, or "auto") and phase_mask= (a path), as --phases and --phase-mask.
PhaseOptions phaseOptions(Keywords& keywords) {
  PhaseOptions options;
  const py::object phases = keywords.take("phases");
  if (py::isinstance<py::str>(phases)) {
    if (phases.cast<std::string>() != "auto") throw OptionError("phases must be auto or a count from 1 to 8");
    options.phases = kAutoPhases;
  } else if (py::isinstance<py::int_>(phases) && !py::isinstance<py::bool_>(phases)) {
    options.phases = phases.cast<int>();
    if (options.phases < 1 || options.phases > kMaxPhases)
      throw OptionError("phases must be auto or a count from 1 to 8, got " + std::to_string(options.phases));
  } else if (!phases.is_none()) {
    keywords.wrongType("phases", "an int or \"auto\"", phases);
  }
  options.maskPath = keywords.path("phase_mask");
  return options;
}

// A number in [-1, 1] or "auto" (fitted); 0 when not given.
std::optional<double> bodyFormOf(Keywords& keywords) {
  const py::object form = keywords.take("body_form");
  if (form.is_none()) return 0.0;
  const char* range = "body_form must be auto or a number from -1 to 1";
  if (py::isinstance<py::str>(form)) {
    if (form.cast<std::string>() != "auto") throw OptionError(range);
    return std::nullopt;
  }
  if (py::isinstance<py::bool_>(form) ||
      !(py::isinstance<py::int_>(form) || py::isinstance<py::float_>(form)))
    keywords.wrongType("body_form", "a number or \"auto\"", form);
  const double value = form.cast<double>();
  if (!(value >= -1 && value <= 1)) throw OptionError(range);
  return value;
}

ParticleSolidOptions particleSolidOptions(Keywords& keywords) {
  ParticleSolidOptions options;
  options.segmentation = segmentationOptions(keywords);
  options.phases = phaseOptions(keywords);
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
  options.bodyForm = bodyFormOf(keywords);
  options.seed = seedOf(keywords);
  options.brickEdge = int(keywords.integer("bricks").value_or(0));
  return options;
}

/// particles(photo, **options): the solid's arrays and report; a .vdb and a report file only when
/// output= and report= are given.
py::dict particles(const py::object& photo, const py::kwargs& kwargs) {
  Keywords keywords("particles", kwargs);
  ParticleSolidOptions options;
  runParsing([&] { options = particleSolidOptions(keywords); });
  options.denseColor = true;  // the colours come back as one array
  const int threads = int(keywords.integer("threads").value_or(0));
  const std::optional<std::string> output = keywords.path("output"), reportPath = keywords.path("report");
  const bool progress = keywords.flag("progress").value_or(false);
  options.timePlacement = progress;
  const py::object xzPhoto = keywords.take("photo_xz"), yzPhoto = keywords.take("photo_yz");
  std::vector<double> pixelSizes;
  if (const py::object sizes = keywords.take("pixel_sizes"); !sizes.is_none()) {
    try {
      pixelSizes = sizes.cast<std::vector<double>>();
    } catch (const py::cast_error&) {
      keywords.wrongType("pixel_sizes", "a sequence of three numbers", sizes);
    }
  }
  keywords.finish();
  std::string name, xzName, yzName;
  const cv::Mat image = photoOf(photo, name);
  cv::Mat xz, yz;  // a material that differs by direction: one given stands for both
  if (!xzPhoto.is_none()) xz = photoOf(xzPhoto, xzName, "photo_xz");
  if (!yzPhoto.is_none()) yz = photoOf(yzPhoto, yzName, "photo_yz");
  if (xz.empty()) xz = yz, xzName = yzName;
  if (yz.empty()) yz = xz, yzName = xzName;
  ParticleSolid solid;
  nlohmann::json report;
  runReleased([&] {
    const ThreadLimit limit(threads);
    if (!pixelSizes.empty()) {
      if (xz.empty())
        throw OptionError(
            "--pixel-sizes brings three planes' photos to one scale: give --photo-xz or --photo-yz");
      const std::array<PixelSize, 3> sizes = *planePixelSizes(pixelSizes, {name, xzName, yzName}, false);
      const double side = squarePixelSide(sizes[0], name);
      const bool oneForBoth = xz.data == yz.data && sizes[1] == sizes[2];
      xz = atPixelSize(xz, sizes[1], side, xzName);
      yz = oneForBoth ? xz : atPixelSize(yz, sizes[2], side, yzName);
    }
    ProgressLine line(progress);
    std::optional<OutputFiles> outputs;
    if (output || reportPath) {
      outputs.emplace();
      for (const std::string& input : {name, xzName, yzName})
        if (!input.empty() && input != "array") outputs->addInput(input);
      if (options.phases.maskPath) outputs->addInput(*options.phases.maskPath);
      if (output) outputs->addFile("output", *output, {".vdb"});
      if (reportPath) outputs->addFile("report", *reportPath, {".json"});
    }
    ParticleSolidBuilder builder(options, [&line](const std::string& step, double fraction) {
      line.update(step, fraction);
      checkInterruption();
    });
    builder.analyze(image, name);
    if (!xz.empty()) builder.analyzePlanes(xz, xzName, yz, yzName);
    builder.makeParticles();
    builder.place();
    solid = builder.finish();
    line.done();
    report = particleSolidReport(solid, options);
    report["time_seconds"] = solid.timer.finish();
    report["peak_memory_mib"] = peakMemoryMiB();
    if (outputs) {
      solid.volume.metadata = particleSolidMetadata(solid, options, "solidtex.particles (Python)");
      if (output) outputs->write(*output, [&](const std::string& path) { writeVdb(path, solid.volume); });
      if (reportPath)
        outputs->write(*reportPath, [&](const std::string& path) { writeJsonFile(path, report); });
      outputs->commit();
    }
    paintColor(solid.volume);  // after writing, which paints the .vdb's leaf by leaf
  });
  const Dims d = solid.volume.dims;
  py::dict result;
  if (std::vector<std::uint8_t> phase = phaseGrid(solid.volume); !phase.empty())
    result["phase"] = ownedArray(std::move(phase), {d.z, d.y, d.x});
  result["particle_id"] = ownedArray(std::move(solid.volume.particleId), {d.z, d.y, d.x});
  result["color"] = ownedArray(interleaved(std::move(solid.volume.color)), {d.z, d.y, d.x, 3});
  const auto placed = py::ssize_t(solid.wholeVolumes.volumes.size());
  result["particle_volumes"] = ownedArray(std::move(solid.wholeVolumes.volumes), {placed});
  result["report"] = toPython(report);
  return result;
}

/// analyze(photo, **options): the photo's particle statistics as a dict, with its label image
/// (particle_labels); the outlined photo as labels= (a PNG) when asked.
py::object analyze(const py::object& photo, const py::kwargs& kwargs) {
  Keywords keywords("analyze", kwargs);
  const SegmentationOptions options = segmentationOptions(keywords);
  const PhaseOptions phases = phaseOptions(keywords);
  const std::uint64_t seed = std::uint64_t(keywords.integer("seed").value_or(1));
  const std::optional<std::string> labels = keywords.path("labels"), reportPath = keywords.path("report");
  keywords.finish();
  std::string name;
  const cv::Mat image = photoOf(photo, name);
  nlohmann::json report;
  std::vector<std::int32_t> particleLabels;
  runReleased([&] {
    std::optional<OutputFiles> outputs;
    if (labels || reportPath) {
      outputs.emplace();
      if (name != "array") outputs->addInput(name);
      if (labels) outputs->addFile("labels", *labels, {".png"});
      if (reportPath) outputs->addFile("report", *reportPath, {".json"});
    }
    ExemplarStats stats = analyzeExemplar(image, name, options);
    const std::optional<ParticlePhases> found = findPhases(stats, phases, seed);
    if (found) assignPhases(stats, *found);
    report = toJson(stats);
    if (found && !found->bic.empty()) report["phase_bic"] = found->bic;
    cv::Mat labelImage = cv::Mat::zeros(image.rows, image.cols, CV_32S);
    for (const Particle2D& p : stats.particles) labelImage(p.box).setTo(p.id, p.mask);
    particleLabels.assign(labelImage.begin<std::int32_t>(), labelImage.end<std::int32_t>());
    if (!outputs) return;
    if (labels)
      outputs->write(*labels, [&](const std::string& path) { writeImage(path, drawLabels(image, stats)); });
    if (reportPath)
      outputs->write(*reportPath, [&](const std::string& path) { writeJsonFile(path, report); });
    outputs->commit();
  });
  py::dict result(toPython(report));
  result["particle_labels"] = ownedArray(std::move(particleLabels), {image.rows, image.cols});
  return result;
}

/// The pixels of an exemplar photo given as a numpy array: (H, W), or (H, W, C) with C <= 4.
bool isPhotoArray(const py::array& array) {
  return array.ndim() == 2 || (array.ndim() == 3 && array.shape(2) <= 4);
}

/// A volume exemplar given as a numpy array: (Z, Y, X) densities or (Z, Y, X, 3) linear RGB.
DenseVolume volumeOf(const py::array& array) {
  if (array.ndim() == 4 && array.shape(3) != 3)
    throw py::value_error("a volume exemplar is (Z, Y, X) densities or (Z, Y, X, 3) colours");
  const auto values = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!values) throw py::value_error("a volume exemplar must hold numbers");
  DenseVolume volume;
  volume.dims = {int(array.shape(2)), int(array.shape(1)), int(array.shape(0))};
  volume.channels = array.ndim() == 4 ? 3 : 1;
  volume.values.assign(values.data(), values.data() + values.size());
  return volume;
}

py::dict photoGrowth(const cv::Mat& exemplar, GrowOptions options, bool measure, bool progress) {
  const Dims dims = options.volume.dims;
  GrowResult result;
  nlohmann::json report;
  runReleased([&] {
    planGrowthMemory(options);
    ProgressLine line(progress);
    options.progress = [&line](const std::string& step, double fraction) {
      line.update(step, fraction);
      checkInterruption();
    };
    result = growSolid(exemplar, options);
    line.done();
    std::optional<ContinuousQuality> quality;
    if (measure) quality = measureGrownSolid(result.volume, exemplar, {});
    report = grownSolidReport(options, result, quality ? &*quality : nullptr, {});
  });
  py::dict arrays;
  arrays["color"] = ownedArray(interleaved(std::move(result.volume.color)), {dims.z, dims.y, dims.x, 3});
  arrays["report"] = toPython(report);
  return arrays;
}

py::dict photoSynthesis(const cv::Mat& exemplar, const std::string& name, Keywords& keywords) {
  SynthesisOptions options;
  runParsing([&] {
    options.method = parseMethod(keywords.text("method").value_or("chen-wang"));
    options.distance = parseDistance(keywords.text("distance").value_or("rgb"));
    options.similaritySearch = parseSimilaritySearch(keywords.text("similarity_search").value_or("auto"));
  });
  options.size = int(keywords.integer("size").value_or(options.size));
  options.levels = int(keywords.integer("levels").value_or(options.levels));
  options.waveletLevels = int(keywords.integer("wavelet_levels").value_or(options.waveletLevels));
  if (const auto sides = keywords.integers("neighborhoods")) options.neighborhoods = *sides;
  options.k = int(keywords.integer("k").value_or(options.k));
  options.iterations = int(keywords.integer("iterations").value_or(options.iterations));
  options.pcaDims = int(keywords.integer("pca_dims").value_or(options.pcaDims));
  options.seed = seedOf(keywords);
  options.threads = int(keywords.integer("threads").value_or(0));
  const std::optional<std::string> control = keywords.path("control");
  const bool measure = keywords.flag("measure").value_or(true),
             progress = keywords.flag("progress").value_or(false);
  const std::optional<std::int64_t> growFrom = keywords.integer("grow_from"),
                                    bricks = keywords.integer("bricks");
  const std::optional<std::vector<int>> dims = keywords.integers("dims", 3);
  const py::object xzPhoto = keywords.take("photo_xz"), yzPhoto = keywords.take("photo_yz");
  keywords.finish();
  options.exemplarName = std::filesystem::path(name).filename().string();
  // A material that differs by direction: the yz, xz and xy planes' exemplars, one given for both.
  std::array<cv::Mat, 3> planes;
  std::array<std::string, 3> planeNames;
  if (!yzPhoto.is_none()) planes[0] = photoOf(yzPhoto, planeNames[0], "photo_yz");
  if (!xzPhoto.is_none()) planes[1] = photoOf(xzPhoto, planeNames[1], "photo_xz");
  if (planes[0].empty()) planes[0] = planes[1], planeNames[0] = planeNames[1];
  if (planes[1].empty()) planes[1] = planes[0], planeNames[1] = planeNames[0];
  planes[2] = exemplar, planeNames[2] = name;
  const bool byPlane = !planes[0].empty();
  for (std::string& planeName : planeNames) planeName = std::filesystem::path(planeName).filename().string();
  const Dims out =
      dims ? Dims{(*dims)[0], (*dims)[1], (*dims)[2]} : Dims{options.size, options.size, options.size};
  const std::optional<int> asked = growFrom ? std::optional<int>(int(*growFrom)) : std::nullopt;
  if (const int seedEdge = growSeedEdge(asked, dims.has_value(), out); seedEdge > 0) {
    runParsing([&] {
      if (byPlane)
        throw OptionError("photo_xz and photo_yz make solids up to size " +
                          std::to_string(kLargestDirectPhotoSolid) + ", not grown ones");
    });
    GrowOptions grow;
    grow.seed = options;
    grow.seed.size = seedEdge;
    grow.volume.dims = out;
    grow.volume.seed = options.seed;
    grow.volume.threads = options.threads;
    grow.brickEdge = int(bricks.value_or(0));
    return photoGrowth(exemplar, grow, measure, progress);
  }
  SynthesisResult result;
  nlohmann::json report;
  runReleased([&] {
    if (control) options.control = loadPhoto(*control);
    ProgressLine line(progress);
    options.progress = [&line](const std::string& step, double fraction) {
      line.update(step, fraction);
      checkInterruption();
    };
    result = byPlane ? synthesizeSolid(planes, options) : synthesizeSolid(exemplar, options);
    line.done();
    std::optional<ContinuousQuality> quality;
    if (measure && !byPlane) quality = measureContinuousSolid(result.volume, exemplar, {}, {});
    report = synthesisReport(options, result.statistics, quality ? &*quality : nullptr, {});
    const ContinuousQualityOptions defaults;
    if (byPlane)
      report["planes"] =
          planeExemplarsReport(result.volume, planes, planeNames, measure ? &defaults : nullptr);
    report["solidtex_version"] = SOLIDTEX_VERSION;
    report["command"] = "synthesize";
  });
  const Dims d = result.volume.dims;
  py::dict arrays;
  arrays["color"] = ownedArray(interleaved(std::move(result.volume.color)), {d.z, d.y, d.x, 3});
  arrays["report"] = toPython(report);
  return arrays;
}

py::dict volumeSynthesis(const DenseVolume& exemplar, const std::string& name, Keywords& keywords) {
  VolumeSynthesisOptions options;
  const int size = int(keywords.integer("size").value_or(64));
  options.dims = {size, size, size};
  if (const auto dims = keywords.integers("dims", 3)) options.dims = {(*dims)[0], (*dims)[1], (*dims)[2]};
  if (const auto box = keywords.integers("region", 6))
    options.region = Box{{(*box)[0], (*box)[1], (*box)[2]}, {(*box)[3], (*box)[4], (*box)[5]}};
  options.levels = int(keywords.integer("levels").value_or(options.levels));
  options.jitter = keywords.number("jitter").value_or(options.jitter);
  options.k = int(keywords.integer("k").value_or(options.k));
  options.exclusion = int(keywords.integer("exclusion").value_or(options.exclusion));
  options.window = int(keywords.integer("appearance").value_or(options.window));
  options.pcaDims = int(keywords.integer("pca_dims").value_or(options.pcaDims));
  options.corrections = int(keywords.integer("corrections").value_or(options.corrections));
  options.periodic = keywords.flag("periodic").value_or(false);
  options.seed = seedOf(keywords);
  options.threads = int(keywords.integer("threads").value_or(0));
  const std::optional<std::string> fieldName = keywords.text("field");
  const bool measure = keywords.flag("measure").value_or(true),
             progress = keywords.flag("progress").value_or(false);
  keywords.finish();
  VolumeSynthesisResult result;
  nlohmann::json report;
  runReleased([&] {
    std::optional<FrameField> field;
    if (fieldName)
      field = std::filesystem::path(*fieldName).extension() == ".vdb"
                  ? readFrameField(*fieldName, options.dims)
                  : builtinFrameField(*fieldName, options.dims);
    options.field = field ? &*field : nullptr;
    ProgressLine line(progress);
    options.progress = [&line](const std::string& step, double fraction) {
      line.update(step, fraction);
      checkInterruption();
    };
    result = synthesizeFromVolume(exemplar, options);
    line.done();
    options.field = nullptr;
    report = volumeSynthesisReport(result, options, exemplar, name, fieldName.value_or("none"));
    if (measure) report["quality"] = volumeQualityReport(result.values, exemplar, {});
  });
  const Dims d = result.values.dims;
  py::dict arrays;
  if (result.values.channels == 3)
    arrays["color"] = ownedArray(std::move(result.values.values), {d.z, d.y, d.x, 3});
  else
    arrays["density"] = ownedArray(std::move(result.values.values), {d.z, d.y, d.x});
  arrays["report"] = toPython(report);
  return arrays;
}

/// synthesize(exemplar, **options): a continuous solid from a photo (path or array) or a volume
/// (a .vdb path or a (Z, Y, X[, 3]) array), as arrays and the report.
py::dict synthesize(const py::object& exemplar, const py::kwargs& kwargs) {
  Keywords keywords("synthesize", kwargs);
  const std::optional<std::string> path = asPath(exemplar);
  if (path && std::filesystem::path(*path).extension() == ".vdb") {
    DenseVolume volume;
    runReleased([&] { volume = readVolumeExemplar(*path); });
    return volumeSynthesis(volume, std::filesystem::path(*path).filename().string(), keywords);
  }
  if (!path && py::isinstance<py::array>(exemplar) &&
      !isPhotoArray(py::reinterpret_borrow<py::array>(exemplar)))
    return volumeSynthesis(volumeOf(py::reinterpret_borrow<py::array>(exemplar)), "array", keywords);
  std::string name;
  const cv::Mat photo = photoOf(exemplar, name);
  return photoSynthesis(photo, name, keywords);
}

/// A solid given as a .vdb path, a dict of arrays as particles() and synthesize() return, or one
/// array: (Z, Y, X, 3) linear RGB, or (Z, Y, X) int32 particle ids.
SolidVolume solidOf(const py::handle& solid, std::string& name) {
  if (const std::optional<std::string> path = asPath(solid)) {
    name = *path;
    SolidVolume volume;
    runReleased([&] { volume = readVdb(*path); });
    return volume;
  }
  name = "array";
  py::dict grids;
  if (py::isinstance<py::dict>(solid)) {
    grids = py::reinterpret_borrow<py::dict>(solid);
  } else if (py::isinstance<py::array>(solid)) {
    const auto array = py::reinterpret_borrow<py::array>(solid);
    grids[array.ndim() == 4 ? "color" : "particle_id"] = array;
  } else {
    throw py::type_error("volume must be a path, a dict of arrays or a numpy array, not " +
                         std::string(py::str(py::type::handle_of(solid).attr("__name__"))));
  }
  SolidVolume volume;
  const auto take = [&](const char* key, int ndim) -> py::array {
    if (!grids.contains(key)) return {};
    const auto array = py::reinterpret_borrow<py::array>(grids[key]);
    if (array.ndim() != ndim) throw py::value_error(std::string("volume's ") + key + " has the wrong shape");
    const Dims dims{int(array.shape(2)), int(array.shape(1)), int(array.shape(0))};
    if (volume.dims.count() > 0 && !(volume.dims == dims))
      throw py::value_error("the volume's arrays differ in shape");
    volume.dims = dims;
    return array;
  };
  if (const py::array ids = take("particle_id", 3)) {
    const auto values = py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>::ensure(ids);
    volume.particleId.assign(values.data(), values.data() + values.size());
  }
  if (const py::array color = take("color", 4)) {
    const auto values = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(color);
    volume.color.resize(std::size_t(values.size() / 3));
    std::memcpy(volume.color.data(), values.data(), std::size_t(values.size()) * sizeof(float));
  }
  if (const py::array density = take("density", 3)) {
    const auto values = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(density);
    volume.density.assign(values.data(), values.data() + values.size());
  }
  if (volume.dims.count() == 0)
    throw py::value_error("the volume has no particle_id, color or density array");
  // What the .vdb's metadata would say: the scale, and whether the faces cut particles.
  if (grids.contains("report")) {
    const py::dict report = grids["report"];
    if (report.contains("volume") && py::dict(report["volume"]).contains("voxels_per_pixel"))
      volume.metadata["voxels_per_pixel"] = py::str(py::dict(report["volume"])["voxels_per_pixel"]);
    if (report.contains("boundary")) volume.metadata["boundary"] = py::str(report["boundary"]);
  }
  if (grids.contains("particle_volumes")) {
    const auto values =
        py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(grids["particle_volumes"]);
    if (!values || values.ndim() != 1) throw py::value_error("volume's particle_volumes must be a 1D array");
    WholeParticleVolumes whole;
    whole.volumes.assign(values.data(), values.data() + values.size());
    for (double v : whole.volumes)
      if (!(v >= 1 && v < 1e15))
        throw py::value_error("volume's particle_volumes must be voxel counts of at least 1");
    const py::dict report = grids.contains("report") ? py::dict(grids["report"]) : py::dict();
    const py::dict volumeReport = report.contains("volume") ? py::dict(report["volume"]) : py::dict();
    if (volumeReport.contains("placed_particles")) {
      const py::dict placed = volumeReport["placed_particles"];
      whole.cutShare = placed["cut_share"].cast<double>();
      whole.cutParticles = placed["cut_particles"].cast<std::size_t>();
    }
    addWholeVolumesMetadata(whole, volume.metadata);
  }
  return volume;
}

/// compare(photo, volume, **options): how well a solid matches its photo, as a dict.
py::object compare(const py::object& photo, const py::object& solid, const py::kwargs& kwargs) {
  Keywords keywords("compare", kwargs);
  CompareJob job;
  runParsing([&] { job.mode = parseCompareMode(keywords.text("mode").value_or("auto")); });
  job.segmentation = segmentationOptions(keywords);
  job.voxelsPerPixel = keywords.number("scale").value_or(0);
  job.sections.offsetsPerAxis = int(keywords.integer("axis_planes").value_or(job.sections.offsetsPerAxis));
  job.sections.obliquePlanes = int(keywords.integer("oblique_planes").value_or(job.sections.obliquePlanes));
  if (const auto plane = keywords.text("plane")) {
    runParsing([&] { job.sections.planeAxis = planeAxisOf(*plane); });
    job.sections.obliquePlanes = 0;
  }
  job.sections.seed = job.quality.seed = seedOf(keywords);
  job.truth = keywords.path("truth");
  if (const auto measures = keywords.text("measures"))
    runParsing([&] { job.measures = parseMeasureSelection(*measures); });
  job.materials.maxDistance = int(keywords.integer("max_distance").value_or(0));
  job.materials.planesPerAxis = int(keywords.integer("measure_planes").value_or(job.materials.planesPerAxis));
  job.phases = int(keywords.integer("phases").value_or(0));
  job.phaseMask = keywords.path("phase_mask");
  const py::object referenceArgument =
      kwargs.contains("reference") ? py::object(kwargs["reference"]) : py::none();
  keywords.take("reference");
  keywords.finish();
  const cv::Mat image = photoOf(photo, job.photo);
  SolidVolume volume;
  if (const std::optional<std::string> path = asPath(solid)) {
    job.volume = *path;
    runReleased([&] { volume = readSolidToCompare(*path, job.mode, job.measuresClasses()); });
  } else {
    volume = solidOf(solid, job.volume);
  }
  cv::Mat reference;
  if (!referenceArgument.is_none()) {
    std::string name;
    reference = photoOf(referenceArgument, name);
    job.reference = name;
  }
  nlohmann::json report;
  runReleased([&] { report = compareSolid(job, image, volume, reference); });
  return toPython(report);
}

}  // namespace
}  // namespace solidtex::python

PYBIND11_MODULE(solidtex, m) {
  using namespace solidtex::python;
  m.doc() =
      "solidtex: one photo of a material in, a 3D solid texture out. Each function takes numpy arrays "
      "or paths and returns numpy arrays and the report as a dict; keywords are the command line's "
      "options spelled as Python names (min_area for --min-area).";
  errorType = new py::object(py::exception<std::runtime_error>(m, "Error", PyExc_RuntimeError));
  m.def("analyze", &analyze, py::arg("photo"),
        "Segments a photo of particles (a path, or a numpy array: (H, W), (H, W, 3) or (H, W, 4), uint8 "
        "or float sRGB in [0, 1]): its statistics (particles, area fraction, area histogram) as a dict, "
        "with particle_labels, an (H, W) int32 array of the particles' ids (0 = background). "
        "Keywords: mask (a path, a bool array or an image array, white = particle), invert, split, outlines, "
        "min_area; phases (an int 1-8 or \"auto\": the particles sorted by colour and grain), phase_mask (a "
        "path), "
        "seed; labels and report write the outlined photo "
        "(PNG) and the statistics (JSON).");
  m.def("particles", &particles, py::arg("photo"),
        "Makes a particle solid from a photo (a path or a numpy array, as analyze takes): a dict of numpy "
        "arrays particle_id (Z, Y, X int32, 0 = matrix), color (Z, Y, X, 3 float32, linear RGB), with "
        "phases phase (Z, Y, X uint8: 0 matrix, 1..K), and the report (a dict). Keywords as the command "
        "line's options: size, dims, scale, placer, sizing, "
        "arrangement, boundary, matrix, particle_texture, views, shapes, smoothing, body_form, bricks, seed, "
        "threads, mask, invert, split, outlines, min_area, phases, phase_mask; photo_xz and photo_yz (the "
        "other "
        "planes' photos of a "
        "material that differs by direction, photo then the xy plane's; one stands for both), pixel_sizes "
        "(their three pixel sides, as --pixel-sizes); output (.vdb) "
        "and report (.json) write files; progress "
        "shows the "
        "progress line. Ctrl-C stops it and leaves no file.");
  m.def("synthesize", &synthesize, py::arg("exemplar"),
        "Synthesises a continuous solid from a photo (a path or a numpy image, as analyze takes) or a "
        "volume (a .vdb path, or a numpy array (Z, Y, X) of densities or (Z, Y, X, 3) of linear RGB): a "
        "dict of numpy arrays (color, or density for a density volume) and the report. Keywords as the "
        "command line's options: size, seed, threads, levels, k, pca_dims; photos: method, "
        "wavelet_levels, neighborhoods, distance, similarity_search, iterations, control, photo_xz and "
        "photo_yz (a material that differs by direction: the exemplar is then the xy plane's; the report's "
        "planes rate each plane's slices against its own); volumes: dims, "
        "region, jitter, exclusion, appearance, corrections, field, periodic. measure=False skips the "
        "quality measure; progress=True shows the progress line.");
  m.def("compare", &compare, py::arg("photo"), py::arg("volume"),
        "Compares a solid with the photo it was made from: the report as a dict. photo as analyze takes; "
        "volume a .vdb path, the dict particles() or synthesize() returns, or an array ((Z, Y, X, 3) "
        "colours or (Z, Y, X) particle ids). Keywords: mode (auto, particles, continuous), reference (a "
        "second photo), scale, axis_planes, oblique_planes, plane (xy, xz or yz: that plane's axis sections "
        "only), seed, truth (a .vdb), mask, invert, split, "
        "outlines, min_area; measures (s2, lineal, chord, psd, minkowski, tortuosity, all, none), "
        "max_distance, "
        "measure_planes, phases (K colour classes), phase_mask (an image of the photo's phases).");
  bindMaterialsDescriptors(m);
}
