// NumPy arrays to and from the libraries' types, with the checks and messages of the library.
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/sphere.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace clumpkit::python {

/// float64, C order: what every array argument is converted to (copied only when it is not).
using Doubles = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;
using Ints = pybind11::array_t<long long, pybind11::array::c_style | pybind11::array::forcecast>;

/// Rows of an (n, 3) array; InvalidInput naming `name` and the shape otherwise (n = 0 allowed
/// only with `allow_empty`).
std::vector<Vec3> points_from(const Doubles& a, const std::string& name, bool allow_empty = false);

/// The clump of centres (n, 3) and radii (n,): shapes checked here, values by validate(Clump)
/// (a non-finite centre or a radius that is not positive, named by index).
Clump clump_from(const Doubles& centres, const Doubles& radii);

/// (n, 3) float64 array of the points; (3,) of one vector; (3, 3) of a matrix.
pybind11::array_t<double> array_of(const std::vector<Vec3>& points);
pybind11::array_t<double> array_of(const Vec3& v);
pybind11::array_t<double> array_of(const Mat3& m);

/// The same value as Python objects (dict, list, float, int, str, bool, None).
pybind11::object python_of(const nlohmann::ordered_json& j);
pybind11::object python_of(const nlohmann::json& j);

}  // namespace clumpkit::python
