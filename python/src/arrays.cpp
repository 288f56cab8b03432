#include "python/src/arrays.h"

#include "geom/errors.h"

namespace py = pybind11;

namespace clumpkit::python {

namespace {

std::string shape_of(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

}  // namespace

std::vector<Vec3> points_from(const Doubles& a, const std::string& name, bool allow_empty) {
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw InvalidInput(name + ": expected an (n, 3) array, got shape " + shape_of(a));
  if (a.shape(0) == 0 && !allow_empty) throw InvalidInput(name + ": the array is empty");
  std::vector<Vec3> points(static_cast<std::size_t>(a.shape(0)));
  const double* p = a.data();
  for (std::size_t i = 0; i < points.size(); ++i)
    points[i] = Vec3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
  return points;
}

Clump clump_from(const Doubles& centres, const Doubles& radii) {
  const std::vector<Vec3> c = points_from(centres, "centres");
  if (radii.ndim() != 1 || radii.shape(0) != static_cast<py::ssize_t>(c.size()))
    throw InvalidInput("radii: expected an (n,) array with n = " + std::to_string(c.size()) +
                       " as the centres, got shape " + shape_of(radii));
  Clump clump;
  clump.spheres.resize(c.size());
  const double* r = radii.data();
  for (std::size_t i = 0; i < c.size(); ++i) clump.spheres[i] = {c[i], r[i]};
  validate(clump);
  return clump;
}

py::array_t<double> array_of(const std::vector<Vec3>& points) {
  py::array_t<double> a({static_cast<py::ssize_t>(points.size()), py::ssize_t(3)});
  double* p = a.mutable_data();
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) p[3 * i + k] = points[i][k];
  return a;
}

py::array_t<double> array_of(const Vec3& v) {
  py::array_t<double> a(py::ssize_t(3));
  for (int k = 0; k < 3; ++k) a.mutable_data()[k] = v[k];
  return a;
}

py::array_t<double> array_of(const Mat3& m) {
  py::array_t<double> a({py::ssize_t(3), py::ssize_t(3)});
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) a.mutable_data()[3 * i + k] = m(i, k);
  return a;
}

namespace {

template <class Json>
py::object convert(const Json& j) {
  if (j.is_object()) {
    py::dict d;
    for (auto it = j.begin(); it != j.end(); ++it) d[py::str(it.key())] = convert(it.value());
    return std::move(d);
  }
  if (j.is_array()) {
    py::list l;
    for (const auto& v : j) l.append(convert(v));
    return std::move(l);
  }
  if (j.is_boolean()) return py::bool_(j.template get<bool>());
  if (j.is_number_integer()) return py::int_(j.template get<long long>());
  if (j.is_number()) return py::float_(j.template get<double>());
  if (j.is_string()) return py::str(j.template get<std::string>());
  return py::none();
}

}  // namespace

py::object python_of(const nlohmann::ordered_json& j) {
  return convert(j);
}
py::object python_of(const nlohmann::json& j) {
  return convert(j);
}

}  // namespace clumpkit::python
