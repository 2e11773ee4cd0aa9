#include "synthesis/synthesizeSolid.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

#include "common/Error.h"
#include "common/Random.h"
#include "common/ThreadLimit.h"
#include "common/interruption.h"
#include "common/secondsSince.h"
#include "common/srgb.h"
#include "synthesis/detail/AxisExemplars.h"
#include "synthesis/detail/ExemplarNeighborhoods.h"
#include "synthesis/detail/ExemplarPyramid.h"
#include "synthesis/detail/HaarPyramid.h"
#include "synthesis/detail/KdTree.h"
#include "synthesis/detail/SimilaritySets.h"
#include "synthesis/detail/SliceMatches.h"
#include "synthesis/detail/discreteSolve.h"
#include "synthesis/detail/histograms.h"
#include "synthesis/detail/rebuildSkeletalSolid.h"
#include "synthesis/detail/upsample.h"
#include "synthesis/detail/weightedAverageSolve.h"

namespace solidtex {

using namespace synthesis::detail;

std::string searchName(NeighborhoodSearch search) {
  switch (search) {
    case NeighborhoodSearch::Exhaustive:
      return "exhaustive";
    case NeighborhoodSearch::KCoherence:
      return "k-coherence";
    case NeighborhoodSearch::KdTree:
      return "kd-tree";
  }
  return "";
}

std::string methodName(Method method) {
  switch (method) {
    case Method::ChenWang:
      return "chen-wang";
    case Method::Kopf:
      return "kopf";
    case Method::Skeletal:
      return "skeletal";
  }
  return "";
}

std::string distanceName(NeighborhoodDistance distance) {
  return distance == NeighborhoodDistance::Rgb ? "rgb" : "wavelet";
}

NeighborhoodDistance parseDistance(const std::string& name) {
  if (name == "rgb") return NeighborhoodDistance::Rgb;
  if (name == "wavelet") return NeighborhoodDistance::Wavelet;
  throw OptionError("unknown neighbourhood distance '" + name + "' (expected rgb or wavelet)");
}

std::string similaritySearchName(SimilaritySearch search) {
  switch (search) {
    case SimilaritySearch::Automatic:
      return "auto";
    case SimilaritySearch::Exact:
      return "exact";
    case SimilaritySearch::Approximate:
      return "approximate";
  }
  return "?";
}

SimilaritySearch parseSimilaritySearch(const std::string& name) {
  for (SimilaritySearch s :
       {SimilaritySearch::Automatic, SimilaritySearch::Exact, SimilaritySearch::Approximate})
    if (name == similaritySearchName(s)) return s;
  throw OptionError("unknown similarity search '" + name + "' (expected auto, exact or approximate)");
}

Method parseMethod(const std::string& name) {
  for (Method m : {Method::ChenWang, Method::Kopf, Method::Skeletal})
    if (name == methodName(m)) return m;
  throw OptionError("unknown synthesis method '" + name + "' (expected chen-wang, kopf or skeletal)");
}

namespace {

using Clock = std::chrono::steady_clock;

std::string sizeText(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

/// Neighbourhood side per level (one value broadcasts); validates everything that does not need the image.
std::vector<int> validate(const cv::Mat& exemplar, const SynthesisOptions& o) {
  if (exemplar.empty()) throw InputError("exemplar image is empty");
  if (o.levels < 1 || o.levels > 8)
    throw OptionError("--levels " + std::to_string(o.levels) + " is out of range (1 to 8)");
  if (o.size < 2 || o.size > 1024)
    throw OptionError("--size " + std::to_string(o.size) + " is out of range (2 to 1024)");
  if (o.k < 1 || o.k > 64) throw OptionError("--k " + std::to_string(o.k) + " is out of range (1 to 64)");
  if (o.iterations < 1 || o.iterations > 100)
    throw OptionError("--iterations " + std::to_string(o.iterations) + " is out of range (1 to 100)");
  if (o.pcaDims < 1 || o.pcaDims > 512)
    throw OptionError("--pca-dims " + std::to_string(o.pcaDims) + " is out of range (1 to 512)");
  if (o.threads < 0) throw OptionError("--threads must not be negative");
  if (o.sparseStep < 1 || o.coherenceRadius < 0 || o.histogramBins < 1)
    throw InputError("invalid synthesis tuning options");
  if (o.method == Method::Skeletal && (o.waveletLevels < 1 || o.waveletLevels >= o.levels))
    throw OptionError("--wavelet-levels " + std::to_string(o.waveletLevels) +
                      " must be at least 1 and below --levels " + std::to_string(o.levels) +
                      ": the coarsest level is optimised");
  std::vector<int> n = o.neighborhoods;
  if (n.size() == 1) n.assign(o.levels, n[0]);
  if (int(n.size()) != o.levels)
    throw OptionError("--neighborhoods lists " + std::to_string(o.neighborhoods.size()) +
                      " sizes but --levels is " + std::to_string(o.levels));
  for (int s : n)
    if (s < 2 || s > 32)
      throw OptionError("neighbourhood size " + std::to_string(s) + " is out of range (2 to 32)");
  const int factor = 1 << (o.levels - 1);
  if (o.size % factor != 0)
    throw OptionError("--size " + std::to_string(o.size) + " cannot be reached by " +
                      std::to_string(o.levels) + " levels (must be a multiple of " + std::to_string(factor) +
                      ")");
  for (int l = 0; l < o.levels; ++l) {
    const int N = o.size >> (o.levels - 1 - l);
    if (N < n[l] || N % o.sparseStep != 0)
      throw OptionError("--size " + std::to_string(o.size) + " is too small for " + std::to_string(o.levels) +
                        " levels: level " + std::to_string(l + 1) + " would be " + std::to_string(N) +
                        "^3 voxels, less than its " + std::to_string(n[l]) + "x" + std::to_string(n[l]) +
                        " neighbourhood");
    int w = exemplar.cols, h = exemplar.rows;
    for (int k = l; k < o.levels - 1; ++k) w /= 2, h /= 2;
    const int extent = NeighborhoodShape{n[l], o.distance == NeighborhoodDistance::Wavelet}.extent();
    if (w < extent || h < extent)
      throw InputError("exemplar " + sizeText(exemplar.cols, exemplar.rows) + " is too small for the " +
                       std::to_string(n[l]) + "x" + std::to_string(n[l]) + " neighbourhood at level " +
                       std::to_string(l + 1) + " of " + std::to_string(o.levels) + " (" + sizeText(w, h) +
                       " there)");
  }
  if (o.control) {
    if (o.control->empty()) throw InputError("control map is empty");
    if (o.control->cols != exemplar.cols || o.control->rows != exemplar.rows)
      throw InputError("control map is " + sizeText(o.control->cols, o.control->rows) +
                       " but the exemplar is " + sizeText(exemplar.cols, exemplar.rows));
  }
  return n;
}

/// Eq. 6's phi: how often each exemplar neighbourhood would be matched if every one were equally
/// often (or as the control map asks), each axis spreading its slice neighbourhoods over its own.
std::vector<double> expectedMatches(const SliceCentreGrid& grid, const ExemplarNeighborhoods& en,
                                    const AxisExemplars& axes, const std::vector<float>& control);

/// The control value at every valid neighbourhood centre (phi(i)), or empty.
std::vector<float> controlAtCentres(const ExemplarNeighborhoods& en, const std::vector<float>& control) {
  if (control.empty()) return {};
  std::vector<float> out(en.count());
  for (int m = 0; m < en.count(); ++m)
    out[m] = control[std::size_t(en.centreY(m)) * en.exemplarWidth + en.centreX(m)];
  return out;
}

std::vector<double> expectedMatches(const SliceCentreGrid& grid, const ExemplarNeighborhoods& en,
                                    const AxisExemplars& axes, const std::vector<float>& control) {
  if (axes.planeHeight == 0)
    return expectedCounts(double(grid.count()), std::size_t(en.count()), controlAtCentres(en, control));
  std::vector<double> phi(std::size_t(en.count()), 0.0);
  for (int axis = 0; axis < 3; ++axis)
    std::fill(phi.begin() + axes.first[axis], phi.begin() + axes.end[axis],
              double(grid.perAxis()) / axes.count(axis));
  return phi;
}

/// The state carried from one level to the next.
struct PyramidState {
  int planes = 1;      ///< 1: one exemplar; 3: the tall image of three planes' exemplars (AxisExemplars)
  AxisExemplars axes;  ///< the last level's
  WorkVolume volume;
  std::vector<std::int64_t> indexHistogram;  ///< slice neighbourhoods matched to each exemplar one
};

/// Chen-wang's discrete solve of one iteration, with its histograms.
void discreteStep(WorkVolume& volume, const RgbImage& ex, const ExemplarNeighborhoods& en,
                  const SliceMatches& matches, const std::vector<double>& theta,
                  std::vector<std::int64_t>& positionHistogram, const ChannelHistograms& exemplarHistogram,
                  ChannelHistograms& volumeHistogram, const SynthesisOptions& o) {
  DiscreteSolveSettings solve;
  solve.irlsExponent = o.irlsExponent;
  solve.choice = o.choice;
  solve.modeBandwidth = o.modeBandwidth;
  const double meanTheta = double(volume.count()) / ex.pixelCount();
  solve.histogramScale = o.histogramReferenceCount > 0 ? o.histogramReferenceCount / meanTheta : 1.0;
  DiscreteHistograms histograms{&theta, &positionHistogram};
  if (o.colorHistogramMatching) {
    histograms.exemplarColors = &exemplarHistogram;
    histograms.volumeColors = &volumeHistogram;
  }
  discreteSolve(volume, ex, en, matches, histograms, solve);
}

/// Level l: its start volume (random or upsampled from state), then search and solve iterations.
LevelStatistics synthesizeLevel(int l, const ExemplarPyramid& pyramid, int neighborhood,
                                const SynthesisOptions& o, PyramidState& state) {
  const auto levelStart = Clock::now();
  const bool chenWang = o.method != Method::Kopf;  // skeletal optimises its skeleton by chen-wang
  const RgbImage& ex = pyramid.levels[l];
  const int N = o.size >> (o.levels - 1 - l);
  const NeighborhoodShape shape{neighborhood, o.distance == NeighborhoodDistance::Wavelet};
  const ExemplarNeighborhoods en = buildExemplarNeighborhoods(ex, shape, o.pcaDims);
  const AxisExemplars& axes = state.axes =
      axisExemplarsOf(en, state.planes > 1 ? ex.height / state.planes : 0);
  const int candidates = axes.count(0);  // each axis searches as many
  const SliceCentreGrid centres{N, o.sparseStep};
  const bool exhaustive = chenWang && candidates < o.exhaustiveBelow &&
                          double(centres.count()) * candidates <= o.exhaustiveBudget;
  SimilaritySets sets;
  std::vector<std::unique_ptr<KdTree>> trees;
  const bool approximate =
      o.similaritySearch == SimilaritySearch::Approximate ||
      (o.similaritySearch == SimilaritySearch::Automatic && candidates >= o.approximateFrom);
  if (chenWang && !exhaustive) sets = buildPlaneSimilaritySets(en, axes, o.k, o.minSeparation, approximate);
  if (!chenWang)
    for (int axis = 0; axis < state.planes; ++axis)
      trees.push_back(
          std::make_unique<KdTree>(en.reducedAt(axes.first[axis]), axes.count(axis), en.reducedDims()));

  LevelStatistics stats;
  stats.volumeSize = N;
  stats.exemplarWidth = ex.width;
  stats.exemplarHeight = ex.height / state.planes;
  stats.neighborhood = shape.size;
  stats.exemplarNeighborhoods = candidates;
  stats.pcaDims = en.reducedDims();
  stats.pcaKeptVariance = en.pca.keptVariance();
  stats.search = exhaustive ? NeighborhoodSearch::Exhaustive
                 : chenWang ? NeighborhoodSearch::KCoherence
                            : NeighborhoodSearch::KdTree;
  stats.similarityLists = sets.lists;
  stats.similarityProbes = sets.probes;
  stats.analysisSeconds = secondsSince(levelStart);

  WorkVolume& volume = state.volume;
  if (l == 0)
    volume = randomVolume(N, ex, deriveSeed(o.seed, 0));
  else if (chenWang)
    volume = upsampleSources(volume, pyramid.levels[l - 1].width, ex);
  else
    volume = upsampleColors(volume);

  SliceMatches matches(centres);
  const std::vector<double> theta =
      expectedCounts(double(volume.count()), std::size_t(ex.pixelCount()), pyramid.control[l]);
  const std::vector<double> phi = expectedMatches(matches.grid, en, axes, pyramid.control[l]);
  std::vector<std::int64_t> positionHistogram;
  if (chenWang) positionHistogram = positionHistogramOf(volume.source, ex.pixelCount());
  const ChannelHistograms exemplarHistogram =
      channelHistograms(ex.data.data(), std::size_t(ex.pixelCount()), o.histogramBins);
  ChannelHistograms volumeHistogram = channelHistograms(volume.rgb.data(), volume.count(), o.histogramBins);
  state.indexHistogram.assign(en.count(), 0);

  SearchSettings search;
  search.sets = chenWang && !exhaustive ? &sets : nullptr;
  for (int axis = 0; axis < 3 && !trees.empty(); ++axis)
    search.trees[axis] = trees[std::size_t(axis) % trees.size()].get();
  search.axes = &axes;
  search.exhaustive = exhaustive;
  search.coherenceRadius = o.coherenceRadius;
  search.phi = chenWang ? &phi : nullptr;
  search.histogramScale =
      std::max(1.0, o.indexReferenceCount * candidates / double(matches.grid.perAxis() * 3 / state.planes));

  for (int it = 0; it < o.iterations; ++it) {
    checkInterruption();
    IterationStatistics step;
    const auto t0 = Clock::now();
    step.energy = searchPhase(volume, en, search, matches, state.indexHistogram);
    step.searchSeconds = secondsSince(t0);
    const auto t1 = Clock::now();
    if (chenWang)
      discreteStep(volume, ex, en, matches, theta, positionHistogram, exemplarHistogram, volumeHistogram, o);
    else
      weightedAverageSolve(volume, ex, en, matches, exemplarHistogram, volumeHistogram, {o.irlsExponent});
    step.solveSeconds = secondsSince(t1);
    if (chenWang) {
      std::int64_t used = 0;
      for (std::int64_t h : positionHistogram) used += h > 0;
      step.positionCoverage = double(used) / double(positionHistogram.size());
    }
    stats.iterations.push_back(step);
    if (o.progress) {
      std::ostringstream line;
      line << methodName(o.method) << " level " << l + 1 << "/" << o.levels << " (" << N << "^3) iteration "
           << it + 1 << "/" << o.iterations << " energy " << step.energy;
      const auto voxels = [&](int level) { return std::pow(double(o.size >> (o.levels - 1 - level)), 3); };
      o.progress(line.str(), pyramidFraction(o.levels, l, it, o.iterations, voxels));
    }
  }
  stats.seconds = secondsSince(levelStart);
  return stats;
}

/// The finished sRGB volume as a SolidVolume: linear colours, and the copied exemplar pixel for
/// chen-wang from one exemplar.
SolidVolume solidVolumeOf(const WorkVolume& volume, const SynthesisOptions& o, int exemplarWidth,
                          int planes) {
  SolidVolume out;
  out.dims = {o.size, o.size, o.size};
  out.color.resize(volume.count());
  for (std::size_t i = 0; i < volume.count(); ++i)
    for (int c = 0; c < 3; ++c) out.color[i][c] = srgbToLinear(volume.rgb[3 * i + c]);
  if (o.method == Method::ChenWang && planes == 1) {
    out.sourcePosition.resize(volume.count());
    for (std::size_t i = 0; i < volume.count(); ++i)
      out.sourcePosition[i] = {float(volume.source[i] % exemplarWidth),
                               float(volume.source[i] / exemplarWidth)};
  }
  out.metadata["method"] = methodName(o.method);
  out.metadata["seed"] = std::to_string(o.seed);
  if (!o.exemplarName.empty()) out.metadata["exemplar"] = o.exemplarName;
  return out;
}

/// The values (one per pixel of a `width`-wide image) of the top-left width x height corner.
std::vector<float> cropValues(const std::vector<float>& values, int fromWidth, int width, int height) {
  if (values.empty()) return values;
  std::vector<float> out;
  out.reserve(std::size_t(width) * std::size_t(height));
  for (int y = 0; y < height; ++y) {
    const auto row = values.begin() + std::ptrdiff_t(y) * fromWidth;
    out.insert(out.end(), row, row + width);
  }
  return out;
}

/// Share of the neighbourhoods the axes match that some slice neighbourhood matched at the end.
double indexCoverage(const PyramidState& state) {
  std::int64_t used = 0, all = 0;
  for (int axis = 0; axis < state.planes; ++axis) {
    for (int m = state.axes.first[axis]; m < state.axes.end[axis]; ++m)
      used += state.indexHistogram[std::size_t(m)] > 0;
    all += state.axes.count(axis);
  }
  return double(used) / double(all);
}

/// Synthesises from `finest` (planes = 1), or from the tall image of three planes' exemplars of
/// equal size, each of a height that every level halves exactly (planes = 3).
SynthesisResult synthesize(RgbImage finest, int planes, const SynthesisOptions& o,
                           std::vector<int> neighborhoods) {
  const auto start = Clock::now();
  SynthesisResult result;
  SynthesisStatistics& stats = result.statistics;
  stats.neighborhoods = std::move(neighborhoods);
  const ThreadLimit threadLimit(o.threads);

  // Skeletal synthesis optimises the coarser levels only and rebuilds the finer ones from the
  // exemplar's Haar details.
  const int rebuilt = o.method == Method::Skeletal ? o.waveletLevels : 0;
  std::vector<float> control = o.control ? toControlValues(*o.control) : std::vector<float>{};
  std::optional<HaarPyramid> haar;
  if (rebuilt > 0) {
    haar = buildHaarPyramid(finest, rebuilt);
    control = cropValues(control, finest.width, haar->finest.width, haar->finest.height);
    finest = haar->finest;
  }
  ExemplarPyramid pyramid = buildExemplarPyramid(finest, o.levels, control);
  SynthesisOptions optimised = o;
  optimised.levels = o.levels - rebuilt;
  optimised.size = o.size >> rebuilt;
  pyramid.levels.resize(std::size_t(optimised.levels));
  pyramid.control.resize(std::size_t(optimised.levels));
  stats.neighborhoods.resize(std::size_t(optimised.levels));
  PyramidState state;
  state.planes = planes;
  for (int l = 0; l < optimised.levels; ++l)
    stats.levels.push_back(synthesizeLevel(l, pyramid, stats.neighborhoods[l], optimised, state));
  if (o.method != Method::Kopf) stats.indexCoverage = indexCoverage(state);
  if (haar) {
    const auto rebuildStart = Clock::now();
    if (o.progress)
      o.progress("skeletal: rebuilding " + std::to_string(o.size) + "^3 from the Haar details", -1);
    state.volume = rebuildSkeletalSolid(state.volume, *haar);
    stats.rebuildSeconds = secondsSince(rebuildStart);
  }
  result.volume = solidVolumeOf(state.volume, o, pyramid.levels.back().width, planes);
  stats.seconds = secondsSince(start);
  return result;
}

/// The three exemplars one above the other, each cut to the rows every level halves exactly.
RgbImage stackPlanes(const std::array<cv::Mat, 3>& exemplarByAxis, int halvings) {
  RgbImage tall;
  for (const cv::Mat& exemplar : exemplarByAxis) {
    const RgbImage plane = toRgbImage(exemplar.rowRange(0, exemplar.rows >> halvings << halvings));
    tall.width = plane.width;
    tall.height += plane.height;
    tall.data.insert(tall.data.end(), plane.data.begin(), plane.data.end());
  }
  return tall;
}

}  // namespace

SynthesisResult synthesizeSolid(const cv::Mat& exemplarSrgb, const SynthesisOptions& o) {
  std::vector<int> neighborhoods = validate(exemplarSrgb, o);
  return synthesize(toRgbImage(exemplarSrgb), 1, o, std::move(neighborhoods));
}

SynthesisResult synthesizeSolid(const std::array<cv::Mat, 3>& exemplarByAxis, const SynthesisOptions& o) {
  std::vector<int> neighborhoods;
  for (const cv::Mat& exemplar : exemplarByAxis) neighborhoods = validate(exemplar, o);
  const cv::Mat& xy = exemplarByAxis[2];
  bool same = true;
  for (const cv::Mat& exemplar : exemplarByAxis) {
    if (exemplar.size() != xy.size())
      throw InputError("the plane exemplars differ in size (" +
                       sizeText(exemplarByAxis[0].cols, exemplarByAxis[0].rows) + ", " +
                       sizeText(exemplarByAxis[1].cols, exemplarByAxis[1].rows) + ", " +
                       sizeText(xy.cols, xy.rows) + "): give them one size");
    same = same && exemplar.type() == xy.type() && cv::norm(exemplar, xy, cv::NORM_INF) == 0;
  }
  if (same) return synthesizeSolid(xy, o);
  if (o.control) throw OptionError("a control map needs one exemplar: give no plane exemplars with it");
  const int halvings = o.levels - 1 + (o.method == Method::Skeletal ? o.waveletLevels : 0);
  return synthesize(stackPlanes(exemplarByAxis, halvings), 3, o, std::move(neighborhoods));
}

}  // namespace solidtex
