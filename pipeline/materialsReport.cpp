#include "pipeline/materialsReport.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>

#include "common/Error.h"
#include "validation/chordLengths.h"
#include "validation/linealPath.h"
#include "validation/localThickness.h"
#include "validation/minkowskiFunctionals.h"
#include "validation/twoPointCorrelation.h"

namespace solidtex {
namespace {

using json = nlohmann::json;
using Curve = std::vector<double>;
constexpr const char* kAxisNames[3] = {"x", "y", "z"};
constexpr int kChordBinWidth = 1, kChordBins = 64;  // the last bin holds the longer chords

// One field's descriptors, or the mean of several (the sections).
struct Descriptors {
  double fraction = 0;
  Curve s2, c2, lineal;  // radial S2; C2 and L along the axes, averaged over them
  std::array<Curve, 3> s2Axes, linealAxes;
  double s2Length = 0, c2Length = 0;
  std::array<std::vector<std::size_t>, 3> chords;
  Curve radii, cumulative;  // local thickness
  double meanRadius = 0;
  MinkowskiDensities minkowski;
};

// A phase and, for a particle phase, its particles' labels (for C2; else empty).
struct Field {
  const PhaseField& phase;
  const std::vector<std::int32_t>& labels;
};

Descriptors describe(const Field& field, const MeasureSelection& m, int R, double largest, bool periodic) {
  Descriptors d;
  const PhaseField& phase = field.phase;
  d.fraction = phase.fraction();
  if (m.twoPoint) {
    const CorrelationCurves s2 = twoPointCorrelation(phase, {R, periodic});
    d.s2 = s2.radial;
    d.s2Axes = s2.axes;
    d.s2Length = s2.correlationLength;
    if (!field.labels.empty()) {
      const CorrelationCurves c2 = twoPointClusterFunction(phase.dims, field.labels, R);
      d.c2 = meanOverAxes(c2.axes);
      d.c2Length = c2.correlationLength;
    }
  }
  if (m.linealPath) {
    d.linealAxes = linealPath(phase, R);
    d.lineal = meanOverAxes(d.linealAxes);
  }
  if (m.chords) d.chords = chordLengths(phase).counts;
  if (m.sizes) {
    const LocalThickness t = localThickness(phase, {25, largest});
    d.radii = t.sizes;
    d.cumulative = t.cumulative;
    double sum = 0, count = 0;
    for (std::size_t i = 0; i < t.radius.size(); ++i)
      if (phase.inside[i]) sum += t.radius[i], count += 1;
    d.meanRadius = count > 0 ? sum / count : 0.0;
  }
  if (m.minkowski) d.minkowski = minkowskiDensities(phase, periodic);
  return d;
}

void addScaled(Curve& sum, const Curve& v, double w) {
  sum.resize(std::max(sum.size(), v.size()), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i) sum[i] += w * v[i];
}

// The mean of the sections' descriptors; their chords pooled, along the solid's axes.
Descriptors meanOf(const std::vector<Descriptors>& parts, const std::vector<int>& normals) {
  Descriptors mean;
  const double w = 1.0 / double(parts.size());
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const Descriptors& d = parts[p];
    mean.fraction += w * d.fraction;
    addScaled(mean.s2, d.s2, w);
    addScaled(mean.c2, d.c2, w);
    addScaled(mean.lineal, d.lineal, w);
    mean.s2Length += w * d.s2Length;
    mean.c2Length += w * d.c2Length;
    addScaled(mean.cumulative, d.cumulative, w);
    mean.radii = d.radii;
    mean.meanRadius += w * d.meanRadius;
    mean.minkowski.fraction += w * d.minkowski.fraction;
    mean.minkowski.boundary += w * d.minkowski.boundary;
    mean.minkowski.euler += w * d.minkowski.euler;
    // A plane across `normal` holds the solid's other two axes, in order, as its x and y.
    int planeAxis = 0;
    for (int a = 0; a < 3; ++a) {
      if (a == normals[p]) continue;
      auto& pooled = mean.chords[std::size_t(a)];
      const auto& counts = d.chords[std::size_t(planeAxis++)];
      pooled.resize(std::max(pooled.size(), counts.size()), 0);
      for (std::size_t l = 0; l < counts.size(); ++l) pooled[l] += counts[l];
    }
  }
  return mean;
}

struct Section {
  PhaseField phase;
  std::vector<std::int32_t> labels;
};

// The plane across `normal` at `layer`: the other two axes, in order, as its x and y.
Section sectionOf(const Field& solid, int normal, int layer) {
  const Dims& d = solid.phase.dims;
  const std::array<int, 3> n{d.x, d.y, d.z};
  const int u = normal == 0 ? 1 : 0, v = normal == 2 ? 1 : 2;
  Section plane;
  plane.phase.dims = {n[std::size_t(u)], n[std::size_t(v)], 1};
  plane.phase.inside.resize(plane.phase.dims.count());
  if (!solid.labels.empty()) plane.labels.resize(plane.phase.dims.count());
  std::size_t i = 0;
  for (int b = 0; b < n[std::size_t(v)]; ++b)
    for (int a = 0; a < n[std::size_t(u)]; ++a, ++i) {
      std::array<int, 3> c{};
      c[std::size_t(normal)] = layer;
      c[std::size_t(u)] = a;
      c[std::size_t(v)] = b;
      const std::size_t at = d.index(c[0], c[1], c[2]);
      plane.phase.inside[i] = solid.phase.inside[at];
      if (!plane.labels.empty()) plane.labels[i] = solid.labels[at];
    }
  return plane;
}

json axesJson(const std::array<Curve, 3>& axes) {
  json out = json::object();
  for (int a = 0; a < 3; ++a)
    if (!axes[std::size_t(a)].empty()) out[kAxisNames[a]] = axes[std::size_t(a)];
  return out;
}

std::vector<std::size_t> pooledChords(const Descriptors& d) {
  std::vector<std::size_t> pooled;
  for (const auto& counts : d.chords) {
    pooled.resize(std::max(pooled.size(), counts.size()), 0);
    for (std::size_t l = 0; l < counts.size(); ++l) pooled[l] += counts[l];
  }
  return pooled;
}

json descriptorsJson(const Descriptors& d, const MeasureSelection& m, int R, bool solid) {
  json out = {{"fraction", d.fraction}};
  if (m.twoPoint) {
    out["s2"] = {{"radial", d.s2}, {"correlation_length", d.s2Length}};
    if (!d.s2Axes[0].empty()) out["s2"]["axes"] = axesJson(d.s2Axes);
    if (!d.c2.empty()) out["c2"] = {{"axis_mean", d.c2}, {"correlation_length", d.c2Length}};
  }
  if (m.linealPath) {
    out["lineal_path"] = {{"axis_mean", d.lineal}};
    if (!d.linealAxes[0].empty()) out["lineal_path"]["axes"] = axesJson(d.linealAxes);
  }
  if (m.chords) {
    json means = json::object(), histograms = json::object();
    for (int a = 0; a < 3; ++a) {
      const auto& counts = d.chords[std::size_t(a)];
      if (counts.empty()) continue;
      means[kAxisNames[a]] = meanChord(counts);
      histograms[kAxisNames[a]] = chordHistogram(counts, kChordBinWidth, kChordBins);
    }
    const std::vector<std::size_t> pooled = pooledChords(d);
    out["chords"] = {{"mean", meanChord(pooled)},
                     {"axis_mean", means},
                     {"bin_width", kChordBinWidth},
                     {"histogram", chordHistogram(pooled, kChordBinWidth, kChordBins)},
                     {"axis_histogram", histograms}};
  }
  if (m.sizes)
    out["local_thickness"] = {
        {"radii", d.radii}, {"cumulative", d.cumulative}, {"mean_radius", d.meanRadius}};
  if (m.minkowski) {
    const MinkowskiDensities& k = d.minkowski;
    out["minkowski"] = solid ? json{{"volume_fraction", k.fraction},
                                    {"surface_density", k.boundary},
                                    {"mean_curvature_density", k.meanCurvature},
                                    {"euler_density", k.euler}}
                             : json{{"area_fraction", k.fraction},
                                    {"perimeter_density", k.boundary},
                                    {"euler_density", k.euler}};
  }
  return out;
}

double ratio(double a, double b) { return b != 0 ? a / b : 0.0; }

double largestDifference(const Curve& a, const Curve& b) {
  double worst = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

// How far a field's curves lie from the photo's.
json distancesJson(const Descriptors& photo, const Descriptors& other, const MeasureSelection& m, int R,
                   bool solid) {
  json out = json::object();
  if (m.twoPoint) {
    out["s2_rms"] = curveDistance(photo.s2, other.s2);
    out["s2_correlation_length_ratio"] = ratio(other.s2Length, photo.s2Length);
    if (!photo.c2.empty() && !other.c2.empty()) out["c2_rms"] = curveDistance(photo.c2, other.c2);
  }
  if (m.linealPath) out["lineal_path_rms"] = curveDistance(photo.lineal, other.lineal);
  if (m.chords) {
    const auto a = pooledChords(photo), b = pooledChords(other);
    const Curve ha = chordHistogram(a, kChordBinWidth, kChordBins),
                hb = chordHistogram(b, kChordBinWidth, kChordBins);
    double l1 = 0;
    for (std::size_t i = 0; i < ha.size(); ++i) l1 += std::abs(ha[i] - hb[i]);
    out["chord_mean_ratio"] = ratio(meanChord(b), meanChord(a));
    out["chord_histogram_l1"] = l1;
  }
  if (m.sizes && !solid) {
    out["local_thickness_cdf_largest_difference"] = largestDifference(photo.cumulative, other.cumulative);
    out["local_thickness_mean_ratio"] = ratio(other.meanRadius, photo.meanRadius);
  }
  if (m.minkowski) {
    const MinkowskiDensities &p = photo.minkowski, &o = other.minkowski;
    out["fraction_difference"] = o.fraction - p.fraction;
    if (solid) {
      // Stereology for isotropic materials: S_V = 4/pi L_A and M_V = 2 pi chi_A of the sections.
      out["surface_density_ratio"] = ratio(o.boundary, 4 / std::numbers::pi * p.boundary);
      out["mean_curvature_density_ratio"] = ratio(o.meanCurvature, 2 * std::numbers::pi * p.euler);
    } else {
      out["perimeter_density_ratio"] = ratio(o.boundary, p.boundary);
      out["euler_density_ratio"] = ratio(o.euler, p.euler);
    }
  }
  return out;
}

json tortuosityJson(const PhaseField& phase, const TortuosityOptions& options) {
  json out = json::object();
  for (int a = 0; a < 3; ++a) {
    try {
      const Tortuosity t = tortuosityFactor(phase, a, options);
      out[kAxisNames[a]] = {{"factor", t.factor},
                            {"effective_diffusivity", t.effectiveDiffusivity},
                            {"connected_fraction", t.connectedFraction},
                            {"iterations", t.iterations},
                            {"relative_residual", t.residual},
                            {"tolerance", options.tolerance},
                            {"flux_mismatch", t.fluxMismatch},
                            {"seconds", t.seconds}};
    } catch (const InputError& e) {
      out[kAxisNames[a]] = {{"percolates", false}, {"message", e.what()}};
    }
  }
  return out;
}

json phaseReport(const PhasePair& pair, const MaterialsOptions& options, int R) {
  const Field photo{pair.photo, pair.photoLabels}, solid{pair.solid, pair.solidLabels};
  const MeasureSelection& m = options.measures;
  const double largest =
      m.sizes ? std::max(largestInscribedRadius(photo.phase), largestInscribedRadius(solid.phase)) : 0;
  const Descriptors ofPhoto = describe(photo, m, R, largest, false);
  std::vector<Descriptors> planes;
  std::vector<int> normals;
  const std::array<int, 3> n{solid.phase.dims.x, solid.phase.dims.y, solid.phase.dims.z};
  for (int a = 0; a < 3; ++a)
    for (int t = 1; t <= options.planesPerAxis; ++t) {
      const Section section = sectionOf(solid, a, t * n[std::size_t(a)] / (options.planesPerAxis + 1));
      planes.push_back(describe({section.phase, section.labels}, m, R, largest, false));
      normals.push_back(a);
    }
  const Descriptors ofSections = meanOf(planes, normals);
  const Descriptors ofSolid = describe(solid, m, R, largest, options.periodic);
  json out = {{"photo", descriptorsJson(ofPhoto, m, R, false)},
              {"sections", descriptorsJson(ofSections, m, R, false)},
              {"solid", descriptorsJson(ofSolid, m, R, true)},
              {"sections_vs_photo", distancesJson(ofPhoto, ofSections, m, R, false)},
              {"solid_vs_photo", distancesJson(ofPhoto, ofSolid, m, R, true)}};
  if (m.tortuosity) out["solid"]["tortuosity"] = tortuosityJson(solid.phase, options.tortuosity);
  return out;
}

}  // namespace

MeasureSelection parseMeasureSelection(const std::string& list) {
  MeasureSelection none{false, false, false, false, false, false};
  if (list == "none") return none;
  if (list == "all") return {true, true, true, true, true, true};
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name == "s2")
      none.twoPoint = true;
    else if (name == "lineal")
      none.linealPath = true;
    else if (name == "chord")
      none.chords = true;
    else if (name == "psd")
      none.sizes = true;
    else if (name == "minkowski")
      none.minkowski = true;
    else if (name == "tortuosity")
      none.tortuosity = true;
    else
      throw OptionError("unknown measure '" + name +
                        "' (expected s2, lineal, chord, psd, minkowski, tortuosity, all or none)");
  }
  return none;
}

std::vector<PhasePair> particleAndMatrixPhases(const cv::Mat& photoLabels, const Dims& dims,
                                               const std::vector<std::int32_t>& ids) {
  std::vector<PhasePair> phases;
  for (bool particles : {true, false}) {
    PhasePair p{particles ? "particles" : "matrix",
                phaseOfLabels(photoLabels, particles),
                phaseOfIds(dims, ids, particles),
                {},
                {}};
    if (particles) {
      p.photoLabels.assign(photoLabels.begin<std::int32_t>(), photoLabels.end<std::int32_t>());
      p.solidLabels = ids;
    }
    phases.push_back(std::move(p));
  }
  return phases;
}

std::vector<PhasePair> classPhases(const cv::Mat& photoClasses, const Dims& dims,
                                   const std::vector<std::uint8_t>& classes, int count) {
  std::vector<PhasePair> phases;
  for (int k = 0; k < count; ++k) {
    PhasePair p{
        "phase_" + std::to_string(k), {{photoClasses.cols, photoClasses.rows, 1}, {}}, {dims, {}}, {}, {}};
    for (auto it = photoClasses.begin<std::int32_t>(); it != photoClasses.end<std::int32_t>(); ++it)
      p.photo.inside.push_back(*it == k);
    p.solid.inside.resize(classes.size());
    for (std::size_t i = 0; i < classes.size(); ++i) p.solid.inside[i] = classes[i] == k;
    phases.push_back(std::move(p));
  }
  return phases;
}

json materialsReport(const std::vector<PhasePair>& phases, const MaterialsOptions& options) {
  if (options.planesPerAxis < 1) throw OptionError("the materials measures need at least one plane per axis");
  if (phases.empty()) throw InputError("the materials measures need at least one phase");
  const Dims& photo = phases.front().photo.dims;
  const int R = correlationMaxDistance(photo, options.maxDistance);
  json out = json::object();
  for (const PhasePair& p : phases) out[p.name] = phaseReport(p, options, R);
  return {{"max_distance", R},
          {"planes_per_axis", options.planesPerAxis},
          {"periodic", options.periodic},
          {"phases", out}};
}

}  // namespace solidtex
