#pragma once
#include <pybind11/pybind11.h>

namespace solidtex::python {

/// The materials descriptors (validation/) on numpy arrays: two_point_correlation,
/// cluster_function, lineal_path, chord_lengths, local_thickness, minkowski, euler_number, tortuosity.
void bindMaterialsDescriptors(pybind11::module_& m);

}  // namespace solidtex::python
