#include "python/materialsBindings.h"

#include <array>
#include <string>

#include "python/binding.h"
#include "validation/chordLengths.h"
#include "validation/linealPath.h"
#include "validation/localThickness.h"
#include "validation/minkowskiFunctionals.h"
#include "validation/tortuosity.h"
#include "validation/twoPointCorrelation.h"

namespace solidtex::python {
namespace {

constexpr const char* kAxisNames[3] = {"x", "y", "z"};

Dims dimsOf(const py::array& array) {
  if (array.ndim() == 2) return {int(array.shape(1)), int(array.shape(0)), 1};
  if (array.ndim() == 3) return {int(array.shape(2)), int(array.shape(1)), int(array.shape(0))};
  throw py::value_error("the field must be an image (Y, X) or a volume (Z, Y, X)");
}

// A phase given as an array whose non-zero values are in it.
PhaseField phaseOf(const py::array& array) {
  const Dims dims = dimsOf(array);
  if (dims.count() == 0) throw py::value_error("the field is empty");
  const auto bytes = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(
      array.dtype().kind() == 'b' ? array : py::array(array.attr("__ne__")(0)));
  PhaseField phase{dims, std::vector<std::uint8_t>(bytes.data(), bytes.data() + dims.count())};
  return phase;
}

py::array_t<double> numpyOf(std::vector<double> values) {
  const auto n = py::ssize_t(values.size());
  return ownedArray(std::move(values), {n});
}

// Curves along each axis the field extends in, by name.
py::dict axesDict(const std::array<std::vector<double>, 3>& axes) {
  py::dict out;
  for (int a = 0; a < 3; ++a)
    if (!axes[std::size_t(a)].empty()) out[kAxisNames[a]] = numpyOf(axes[std::size_t(a)]);
  return out;
}

py::dict curvesDict(const CorrelationCurves& c) {
  py::dict out = axesDict(c.axes);
  if (!c.radial.empty()) out["radial"] = numpyOf(c.radial);
  out["phase_fraction"] = c.phaseFraction;
  out["correlation_length"] = c.correlationLength;
  return out;
}

py::dict twoPoint(const py::array& field, bool periodic, int maxDistance) {
  const PhaseField phase = phaseOf(field);
  CorrelationCurves c;
  runReleased([&] { c = twoPointCorrelation(phase, {maxDistance, periodic}); });
  return curvesDict(c);
}

py::dict clusterFunction(const py::array& labels, int maxDistance) {
  const Dims dims = dimsOf(labels);
  const auto ids = py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>::ensure(labels);
  std::vector<std::int32_t> values(ids.data(), ids.data() + dims.count());
  CorrelationCurves c;
  runReleased([&] { c = twoPointClusterFunction(dims, values, maxDistance); });
  return curvesDict(c);
}

py::dict lineal(const py::array& field, int maxDistance) {
  const PhaseField phase = phaseOf(field);
  std::array<std::vector<double>, 3> curves;
  runReleased([&] { curves = linealPath(phase, maxDistance); });
  return axesDict(curves);
}

py::dict chords(const py::array& field, bool keepCut) {
  const PhaseField phase = phaseOf(field);
  ChordLengths c;
  runReleased([&] { c = chordLengths(phase, keepCut); });
  py::dict out;
  for (int a = 0; a < 3; ++a) {
    auto& counts = c.counts[std::size_t(a)];
    if (counts.empty()) continue;
    std::vector<std::int64_t> values(counts.begin(), counts.end());
    const auto n = py::ssize_t(values.size());
    out[kAxisNames[a]] = ownedArray(std::move(values), {n});
  }
  return out;
}

py::dict thickness(const py::array& field, int sizes) {
  const PhaseField phase = phaseOf(field);
  LocalThickness t;
  runReleased([&] { t = localThickness(phase, {sizes}); });
  std::vector<py::ssize_t> shape;
  for (py::ssize_t d = 0; d < field.ndim(); ++d) shape.push_back(field.shape(d));
  py::dict out;
  out["thickness"] = ownedArray(std::move(t.radius), shape);
  out["radii"] = numpyOf(std::move(t.sizes));
  out["cumulative"] = numpyOf(std::move(t.cumulative));
  return out;
}

py::dict minkowski(const py::array& field, bool periodic) {
  const PhaseField phase = phaseOf(field);
  MinkowskiDensities m;
  runReleased([&] { m = minkowskiDensities(phase, periodic); });
  py::dict out;
  out["fraction"] = m.fraction;
  out[phase.isImage() ? "perimeter_density" : "surface_density"] = m.boundary;
  if (!phase.isImage()) out["mean_curvature_density"] = m.meanCurvature;
  out["euler_density"] = m.euler;
  return out;
}

// scikit-image's numbering: 1 = face neighbours; 2 (images) or 3 (volumes) = all neighbours.
std::int64_t eulerNumber(const py::array& field, int connectivity) {
  const PhaseField phase = phaseOf(field);
  const int all = phase.isImage() ? 2 : 3;
  if (connectivity != 1 && connectivity != all)
    throw py::value_error("connectivity must be 1 or " + std::to_string(all) + " for this field");
  std::int64_t chi = 0;
  runReleased([&] {
    chi = eulerCharacteristic(phase, connectivity == 1 ? Connectivity::Faces : Connectivity::Vertices);
  });
  return chi;
}

py::dict tortuosity(const py::array& field, int axis, double tolerance) {
  const PhaseField phase = phaseOf(field);
  if (axis < 0 || axis >= field.ndim()) throw py::value_error("axis must index the field's dimensions");
  Tortuosity t;
  // numpy's axis 0 is the slowest: z in a volume, y in an image.
  const int libraryAxis = field.ndim() - 1 - axis;
  runReleased([&] { t = tortuosityFactor(phase, libraryAxis, {tolerance}); });
  py::dict out;
  out["factor"] = t.factor;
  out["effective_diffusivity"] = t.effectiveDiffusivity;
  out["phase_fraction"] = t.fraction;
  out["connected_fraction"] = t.connectedFraction;
  out["iterations"] = t.iterations;
  out["relative_residual"] = t.residual;
  out["flux_mismatch"] = t.fluxMismatch;
  return out;
}

}  // namespace

void bindMaterialsDescriptors(py::module_& m) {
  const char* field = "field: a numpy image (Y, X) or volume (Z, Y, X); its non-zero values are the phase. ";
  m.def("two_point_correlation", &twoPoint, py::arg("field"), py::arg("periodic") = false,
        py::arg("max_distance") = 0,
        (std::string(
             "Two-point correlation S2(r) of a phase by FFT: arrays x, y, (z) along the axes and radial, "
             "r = 0..max_distance voxels (0: a quarter of the shortest side); zero-padded and normalised "
             "by the overlap unless periodic. ") +
         field)
            .c_str());
  m.def("cluster_function", &clusterFunction, py::arg("labels"), py::arg("max_distance") = 0,
        "Two-point cluster function C2(r) of labelled particles (int array, 0 = none) along the axes.");
  m.def("lineal_path", &lineal, py::arg("field"), py::arg("max_distance"),
        (std::string("Lineal path L(r) along each axis, r = 0..max_distance. ") + field).c_str());
  m.def("chord_lengths", &chords, py::arg("field"), py::arg("keep_cut") = false,
        (std::string("Chord counts by length in voxels along each axis (index = length); chords the field's "
                     "faces cut are left out unless keep_cut. ") +
         field)
            .c_str());
  m.def(
      "local_thickness", &thickness, py::arg("field"), py::arg("sizes") = 25,
      (std::string("Local thickness (float32 radius per voxel), the radii sampled and the share of the phase "
                   "at least that thick. ") +
       field)
          .c_str());
  m.def("minkowski", &minkowski, py::arg("field"), py::arg("periodic") = false,
        (std::string("Minkowski densities per voxel: fraction, surface (perimeter) density, mean curvature "
                     "density (volumes), Euler density. ") +
         field)
            .c_str());
  m.def(
      "euler_number", &eulerNumber, py::arg("field"), py::arg("connectivity"),
      (std::string("Euler characteristic as scikit-image's euler_number: connectivity 1 (face neighbours) or "
                   "2 / 3 (all neighbours in an image / a volume). ") +
       field)
          .c_str());
  m.def("tortuosity", &tortuosity, py::arg("field"), py::arg("axis") = 0, py::arg("tolerance") = 1e-6,
        (std::string(
             "Tortuosity factor of a phase along numpy axis `axis` (steady diffusion between the two "
             "faces, conjugate gradients to `tolerance`); solidtex.Error when it does not percolate. ") +
         field)
            .c_str());
}

}  // namespace solidtex::python
