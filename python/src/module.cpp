// The Python module clumpkit._core: the libraries' API with NumPy arrays in and out.
#include "geom/version.h"
#include "python/src/run.h"

#include <pybind11/pybind11.h>

namespace clumpkit::python {
void bind_geometry(pybind11::module_& m);
void bind_pipelines(pybind11::module_& m);
}  // namespace clumpkit::python

PYBIND11_MODULE(_core, m) {
  m.doc() =
      "clumpkit: irregular particles, sphere clumps with exact mass properties, and DEM "
      "specimens. Lengths in the units of the input (SI for specimens).";
  // The version and commit of the libraries linked in: `clumpkit --version`'s.
  m.attr("__version__") = clumpkit::version();
  m.attr("__commit__") = clumpkit::commit();
  clumpkit::python::register_exceptions();
  clumpkit::python::bind_geometry(m);
  clumpkit::python::bind_pipelines(m);
}
