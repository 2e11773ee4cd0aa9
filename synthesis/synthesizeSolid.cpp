#include "synthesis/synthesizeSolid.h"

#include <chrono>
#include <fstream>
#include <memory>
#include <sstream>

#include <tbb/global_control.h>

#include "common/Error.h"
#include "common/Random.h"
#include "synthesis/ColorSpace.h"
#include "synthesis/ExemplarNeighborhoods.h"
#include "synthesis/ExemplarPyramid.h"
#include "synthesis/Histograms.h"
#include "synthesis/KdTree.h"
#include "synthesis/KopfSolver.h"
#include "synthesis/SimilaritySets.h"
#include "synthesis/SliceMatches.h"
#include "synthesis/SolidMeasures.h"
#include "synthesis/Upsample.h"

namespace solidtex {

using namespace synthesis;

std::string methodName(Method method) { return method == Method::ChenWang ? "chen-wang" : "kopf"; }

Method parseMethod(const std::string& name) {
  if (name == "chen-wang") return Method::ChenWang;
  if (name == "kopf") return Method::Kopf;
  throw InputError("unknown synthesis method '" + name + "' (expected chen-wang or kopf)");
}

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// Peak resident memory of the process in MiB (Linux VmHWM), 0 when unknown.
double peakMemoryMiB() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0;
}

std::string sizeText(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

/// Neighbourhood side per level (one value broadcasts); validates everything that does not need the image.
std::vector<int> validate(const cv::Mat& exemplar, const SynthesisOptions& o) {
  if (exemplar.empty()) throw InputError("exemplar image is empty");
  if (o.levels < 1 || o.levels > 8) throw InputError("--levels " + std::to_string(o.levels) + " is out of range (1 to 8)");
  if (o.size < 2 || o.size > 1024) throw InputError("--size " + std::to_string(o.size) + " is out of range (2 to 1024)");
  if (o.k < 1 || o.k > 64) throw InputError("--k " + std::to_string(o.k) + " is out of range (1 to 64)");
  if (o.iterations < 1 || o.iterations > 100) throw InputError("--iterations " + std::to_string(o.iterations) + " is out of range (1 to 100)");
  if (o.pcaDims < 1) throw InputError("--pca-dims must be at least 1");
  if (o.threads < 0) throw InputError("--threads must not be negative");
  if (o.sparseStep < 1 || o.coherenceRadius < 0 || o.histogramBins < 1) throw InputError("invalid synthesis tuning options");
  std::vector<int> n = o.neighborhoods;
  if (n.size() == 1) n.assign(o.levels, n[0]);
  if (int(n.size()) != o.levels)
    throw InputError("--neighborhoods lists " + std::to_string(o.neighborhoods.size()) + " sizes but --levels is " + std::to_string(o.levels));
  for (int s : n)
    if (s < 2 || s > 32) throw InputError("neighbourhood size " + std::to_string(s) + " is out of range (2 to 32)");
  const int factor = 1 << (o.levels - 1);
  if (o.size % factor != 0)
    throw InputError("--size " + std::to_string(o.size) + " cannot be reached by " + std::to_string(o.levels) + " levels (must be a multiple of " +
                     std::to_string(factor) + ")");
  for (int l = 0; l < o.levels; ++l) {
    const int N = o.size >> (o.levels - 1 - l);
    if (N < n[l] || N % o.sparseStep != 0)
      throw InputError("--size " + std::to_string(o.size) + " is too small for " + std::to_string(o.levels) + " levels: level " + std::to_string(l + 1) +
                       " would be " + std::to_string(N) + "^3 voxels, less than its " + std::to_string(n[l]) + "x" + std::to_string(n[l]) +
                       " neighbourhood");
    int w = exemplar.cols, h = exemplar.rows;
    for (int k = l; k < o.levels - 1; ++k) w /= 2, h /= 2;
    if (w < n[l] || h < n[l])
      throw InputError("exemplar " + sizeText(exemplar.cols, exemplar.rows) + " is too small for the " + std::to_string(n[l]) + "x" +
                       std::to_string(n[l]) + " neighbourhood at level " + std::to_string(l + 1) + " of " + std::to_string(o.levels) + " (" +
                       sizeText(w, h) + " there)");
  }
  if (o.control) {
    if (o.control->empty()) throw InputError("control map is empty");
    if (o.control->cols != exemplar.cols || o.control->rows != exemplar.rows)
      throw InputError("control map is " + sizeText(o.control->cols, o.control->rows) + " but the exemplar is " +
                       sizeText(exemplar.cols, exemplar.rows));
  }
  return n;
}

/// The control value at every valid neighbourhood centre (phi(i)), or empty.
std::vector<float> controlAtCentres(const ExemplarNeighborhoods& en, const std::vector<float>& control) {
  if (control.empty()) return {};
  std::vector<float> out(en.count());
  for (int m = 0; m < en.count(); ++m) out[m] = control[std::size_t(en.centreY(m)) * en.exemplarWidth + en.centreX(m)];
  return out;
}

} // namespace

SynthesisResult synthesizeSolid(const cv::Mat& exemplarSrgb, const SynthesisOptions& o) {
  const auto start = Clock::now();
  const std::vector<int> neighborhoods = validate(exemplarSrgb, o);
  std::unique_ptr<tbb::global_control> threadLimit;
  if (o.threads > 0) threadLimit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, o.threads);
  auto progress = [&](const std::string& line) {
    if (o.progress) o.progress(line);
  };
  const bool chenWang = o.method == Method::ChenWang;

  const RgbImage finest = toRgbImage(exemplarSrgb);
  const std::vector<float> control = o.control ? toControlValues(*o.control) : std::vector<float>{};
  const ExemplarPyramid pyramid = buildExemplarPyramid(finest, o.levels, control);

  nlohmann::json report;
  report["method"] = methodName(o.method);
  report["size"] = o.size;
  report["levels"] = o.levels;
  report["neighborhoods"] = neighborhoods;
  report["k"] = o.k;
  report["iterations"] = o.iterations;
  report["pcaDims"] = o.pcaDims;
  if (chenWang) report["colourHistogramMatching"] = o.colourHistogramMatching;
  report["seed"] = o.seed;
  report["control"] = bool(o.control);
  report["exemplar"] = {{"name", o.exemplarName}, {"width", finest.width}, {"height", finest.height}};
  nlohmann::json levelReports = nlohmann::json::array();

  WorkVolume volume;
  std::vector<std::int64_t> indexHistogram;
  int indexCount = 0;
  for (int l = 0; l < o.levels; ++l) {
    const auto levelStart = Clock::now();
    const RgbImage& ex = pyramid.levels[l];
    const int N = o.size >> (o.levels - 1 - l);
    const NeighborhoodShape shape{neighborhoods[l]};
    const ExemplarNeighborhoods en = buildExemplarNeighborhoods(ex, shape, o.pcaDims);
    const SliceCentreGrid centres{N, o.sparseStep};
    const bool exhaustive =
        chenWang && en.count() < o.exhaustiveBelow && double(centres.count()) * en.count() <= o.exhaustiveBudget;
    SimilaritySets sets;
    std::unique_ptr<KdTree> tree;
    if (chenWang && !exhaustive) sets = buildSimilaritySets(en, o.k, o.minSeparation);
    if (!chenWang) tree = std::make_unique<KdTree>(en.reduced.data(), en.count(), en.reducedDims());
    const double analysisSeconds = secondsSince(levelStart);

    if (l == 0) volume = randomVolume(N, ex, deriveSeed(o.seed, 0));
    else if (chenWang) volume = upsampleSources(volume, pyramid.levels[l - 1].width, ex);
    else volume = upsampleColors(volume);

    SliceMatches matches(centres);
    const std::vector<double> theta = expectedCounts(double(volume.count()), std::size_t(ex.pixelCount()), pyramid.control[l]);
    const std::vector<double> phi = expectedCounts(double(matches.grid.count()), std::size_t(en.count()), controlAtCentres(en, pyramid.control[l]));
    std::vector<std::int64_t> positionHistogram;
    if (chenWang) positionHistogram = positionHistogramOf(volume.source, ex.pixelCount());
    const ChannelHistograms exemplarHistogram = channelHistograms(ex.data.data(), std::size_t(ex.pixelCount()), o.histogramBins);
    ChannelHistograms volumeHistogram = channelHistograms(volume.rgb.data(), volume.count(), o.histogramBins);
    indexHistogram.assign(en.count(), 0);
    indexCount = en.count();

    SearchSettings search;
    search.sets = chenWang && !exhaustive ? &sets : nullptr;
    search.tree = tree.get();
    search.exhaustive = exhaustive;
    search.coherenceRadius = o.coherenceRadius;
    search.phi = chenWang ? &phi : nullptr;
    search.histogramScale = std::max(1.0, o.indexReferenceCount * en.count() / double(matches.grid.count()));

    nlohmann::json iterations = nlohmann::json::array();
    for (int it = 0; it < o.iterations; ++it) {
      const auto t0 = Clock::now();
      const double energy = searchPhase(volume, en, search, matches, indexHistogram);
      const double searchSeconds = secondsSince(t0);
      const auto t1 = Clock::now();
      if (chenWang) {
        DiscreteSolveSettings solve;
        solve.irlsExponent = o.irlsExponent;
        solve.choice = o.choice;
        solve.modeBandwidth = o.modeBandwidth;
        const double meanTheta = double(volume.count()) / ex.pixelCount();
        solve.histogramScale = o.histogramReferenceCount > 0 ? o.histogramReferenceCount / meanTheta : 1.0;
        DiscreteHistograms histograms{&theta, &positionHistogram};
        if (o.colourHistogramMatching) {
          histograms.exemplarColours = &exemplarHistogram;
          histograms.volumeColours = &volumeHistogram;
        }
        discreteSolve(volume, ex, en, matches, histograms, solve);
      }
      else weightedAverageSolve(volume, ex, en, matches, exemplarHistogram, volumeHistogram, {o.irlsExponent});
      const double solveSeconds = secondsSince(t1);
      nlohmann::json entry = {{"iteration", it + 1}, {"energy", energy}, {"searchSeconds", searchSeconds}, {"solveSeconds", solveSeconds}};
      if (chenWang) {
        std::int64_t used = 0;
        for (std::int64_t h : positionHistogram) used += h > 0;
        entry["positionCoverage"] = double(used) / double(positionHistogram.size());
      }
      iterations.push_back(entry);
      std::ostringstream line;
      line << methodName(o.method) << " level " << l + 1 << "/" << o.levels << " (" << N << "^3) iteration " << it + 1 << "/" << o.iterations
           << " energy " << energy;
      progress(line.str());
    }
    levelReports.push_back({{"level", l + 1},
                            {"volumeSize", N},
                            {"exemplarWidth", ex.width},
                            {"exemplarHeight", ex.height},
                            {"neighborhood", shape.size},
                            {"exemplarNeighborhoods", en.count()},
                            {"pcaDims", en.reducedDims()},
                            {"pcaKeptVariance", en.pca.keptVariance()},
                            {"search", exhaustive ? "exhaustive" : (chenWang ? "k-coherence" : "kd-tree")},
                            {"analysisSeconds", analysisSeconds},
                            {"iterations", iterations},
                            {"seconds", secondsSince(levelStart)}});
  }
  report["levelReports"] = levelReports;

  SynthesisResult result;
  SolidVolume& out = result.volume;
  out.dims = {o.size, o.size, o.size};
  out.color.resize(volume.count());
  for (std::size_t i = 0; i < volume.count(); ++i)
    for (int c = 0; c < 3; ++c) out.color[i][c] = srgbToLinearChannel(volume.rgb[3 * i + c]);
  if (chenWang) {
    out.sourcePosition.resize(volume.count());
    for (std::size_t i = 0; i < volume.count(); ++i)
      out.sourcePosition[i] = {float(volume.source[i] % finest.width), float(volume.source[i] / finest.width)};
  }
  out.metadata["method"] = methodName(o.method);
  out.metadata["seed"] = std::to_string(o.seed);
  if (!o.exemplarName.empty()) out.metadata["exemplar"] = o.exemplarName;
  report["synthesisSeconds"] = secondsSince(start);

  if (o.measure) {
    const auto t = Clock::now();
    const SliceEnergy energy = sliceEnergy(volume, finest, o.measureOptions);
    const PositionHistogramStats positions = positionHistogramStats(volume.source, finest.pixelCount());
    std::int64_t usedIndices = 0;
    for (std::int64_t h : indexHistogram) usedIndices += h > 0;
    report["quality"] = {{"energyAxis", energy.axis},
                         {"energyOblique", energy.oblique},
                         {"energyExponent", kSliceEnergyExponent},
                         {"energyAxisSquared", energy.axisSquared},
                         {"energyObliqueSquared", energy.obliqueSquared},
                         {"energyNeighborhood", std::min({o.measureOptions.neighborhood, finest.width, finest.height})},
                         {"positionCoverage", positions.coverage},
                         {"positionFlatness", positions.flatness},
                         {"positionVariation", positions.variation},
                         {"positionSource", chenWang ? "copied pixel" : "dominant proposal"},
                         {"indexCoverage", indexCount ? double(usedIndices) / indexCount : 0.0},
                         {"colorHistogramDistance", colorHistogramDistance(volume.rgb.data(), volume.count(), finest, o.measureOptions.histogramBins)},
                         {"seconds", secondsSince(t)}};
  }
  report["seconds"] = secondsSince(start);
  report["peakMemoryMiB"] = peakMemoryMiB();
  result.report = std::move(report);
  return result;
}

} // namespace solidtex
