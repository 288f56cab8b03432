// Bindings of the geometry: meshes, shape generators, descriptors, the sphere fill, mass
// properties and volumes of unions of spheres.
#include "geom/descriptors/descriptors.h"
#include "geom/errors.h"
#include "geom/fill/fill.h"
#include "geom/random.h"
#include "geom/shapes/block.h"
#include "geom/shapes/hull.h"
#include "geom/shapes/polyhedron.h"
#include "geom/shapes/primitives.h"
#include "geom/template/clump_template.h"
#include "geom/volume/union_of_balls.h"
#include "io/formats/descriptor_table.h"
#include "io/formats/mesh_io.h"
#include "io/pipeline/fill.h"
#include "io/pipeline/volume.h"
#include "python/src/arrays.h"
#include "python/src/run.h"

#include <pybind11/stl.h>

#include <cmath>
#include <optional>

namespace py = pybind11;
using namespace py::literals;

namespace clumpkit::python {

namespace {

// A mesh made from arrays: indices and values checked as read_mesh checks a file's.
Mesh mesh_from(const Doubles& vertices, const Ints& triangles, bool check) {
  Mesh mesh;
  mesh.vertices = points_from(vertices, "vertices");
  if (triangles.ndim() != 2 || triangles.shape(1) != 3)
    throw InvalidInput("triangles: expected an (m, 3) array of vertex indices, got " +
                       std::to_string(triangles.ndim()) + " dimensions");
  if (triangles.shape(0) == 0) throw InvalidInput("triangles: the array is empty");
  mesh.triangles.resize(static_cast<std::size_t>(triangles.shape(0)));
  const long long* t = triangles.data();
  const long long n = static_cast<long long>(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const long long v = t[3 * i + k];
      if (v < 0 || v >= n)
        throw InvalidInput("triangles: triangle " + std::to_string(i) + " has vertex index " +
                           std::to_string(v) + ", outside 0.." + std::to_string(n - 1));
      mesh.triangles[i][k] = static_cast<int>(v);
    }
  if (check) validate_solid(mesh, "mesh");
  return mesh;
}

py::array_t<long long> triangles_of(const Mesh& mesh) {
  py::array_t<long long> a({static_cast<py::ssize_t>(mesh.triangles.size()), py::ssize_t(3)});
  long long* p = a.mutable_data();
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) p[3 * i + k] = mesh.triangles[i][k];
  return a;
}

// Mass properties of a union of spheres at a density.
struct UnionMass {
  UnionProperties u;
  double density = 1.0;
  Vec3 moments = Vec3::Zero();
  Mat3 axes = Mat3::Identity();
};

}  // namespace

namespace {

// Meshes and the shape generators.
void bind_meshes(py::module_& m) {
  py::class_<Mesh>(m, "Mesh",
                   "Closed triangle mesh, triangles counter-clockwise seen from outside (units "
                   "of the caller: every length the functions return is in them)")
      .def(py::init([](const Doubles& vertices, const Ints& triangles, bool check) {
             return mesh_from(vertices, triangles, check);
           }),
           "vertices"_a, "triangles"_a, "check"_a = true,
           "Vertices (n, 3) and triangles (m, 3) of vertex indices. With check, the mesh is "
           "checked and repaired as read_mesh does a file (finite, closed, manifold, oriented "
           "outward: an inward mesh is flipped); ValueError names what is wrong.")
      .def_property_readonly(
          "vertices", [](const Mesh& mesh) { return array_of(mesh.vertices); },
          "(n, 3) float64 copy of the vertices")
      .def_property_readonly("triangles", &triangles_of, "(m, 3) int64 copy of the triangles")
      .def_property_readonly("volume", &signed_volume, "Enclosed volume (divergence theorem)")
      .def_property_readonly("area", &surface_area, "Surface area")
      .def_property_readonly(
          "centroid", [](const Mesh& mesh) { return array_of(solid_centroid(mesh)); },
          "Centroid of the enclosed solid")
      .def(
          "write", [](const Mesh& mesh, const std::string& path) { write_mesh(path, mesh); },
          "path"_a, py::call_guard<py::gil_scoped_release>(),
          "Writes .stl (binary), .obj or .ply by the extension, atomically")
      .def("__repr__", [](const Mesh& mesh) {
        return "<clumpkit.Mesh " + std::to_string(mesh.vertices.size()) + " vertices, " +
               std::to_string(mesh.triangles.size()) + " triangles>";
      });

  m.def(
      "read_mesh",
      [](const std::string& path, double weld_tolerance) {
        MeshReadOptions o;
        o.weld_tolerance = weld_tolerance;
        return read_mesh(path, nullptr, o);
      },
      "path"_a, "weld_tolerance"_a = 0.0, py::call_guard<py::gil_scoped_release>(),
      "Reads STL, OBJ or PLY as `clumpkit fill` does (welded, checked, oriented outward)");

  const BlockParams block;
  m.def(
      "block",
      [](double L, double W, double H, int nd, double sl, double su, std::uint64_t seed) {
        BlockParams p{L, W, H, nd, sl, su};
        Rng rng(seed);
        return make_block(p, rng);
      },
      "L"_a, "W"_a, "H"_a, "nd"_a = block.nd, "sl"_a = block.sl, "su"_a = block.su, "seed"_a = 1,
      py::call_guard<py::gil_scoped_release>(),
      "Rock block of Jin et al. 2017 §2.1 (`clumpkit shape block`): cuboid L × W × H along x, "
      "y, z, edges split in nd, node radii scaled by U(sl, su)");
  const HullParams hull;
  m.def(
      "hull",
      [](double diameter, int points, std::pair<double, double> roundness, double aspect_min,
         int max_attempts, std::uint64_t seed) {
        HullParams p;
        p.diameter = diameter;
        p.points = points;
        p.roundness_min = roundness.first;
        p.roundness_max = roundness.second;
        p.aspect_min = aspect_min;
        p.max_attempts = max_attempts;
        Rng rng(seed);
        return make_hull(p, rng).mesh;
      },
      "diameter"_a, "points"_a = hull.points,
      "roundness"_a = std::make_pair(hull.roundness_min, hull.roundness_max),
      "aspect_min"_a = hull.aspect_min, "max_attempts"_a = hull.max_attempts, "seed"_a = 1,
      py::call_guard<py::gil_scoped_release>(),
      "Random convex hull of Zhang & Zhou 2015 §2.1 (`clumpkit shape hull`): points on a "
      "sphere of the diameter, redrawn until the weighted roundness is in (min, max)");
  const PolyhedronParams poly;
  m.def(
      "polyhedron",
      [](double diameter, int planes, double E, double F, double offset_min, double offset_max,
         std::uint64_t seed) {
        PolyhedronParams p;
        p.diameter = diameter;
        p.planes = planes;
        p.E = E;
        p.F = F;
        p.offset_min = offset_min;
        p.offset_max = offset_max;
        Rng rng(seed);
        return make_polyhedron(p, rng);
      },
      "diameter"_a, "planes"_a = poly.planes, "E"_a = poly.E, "F"_a = poly.F,
      "offset_min"_a = poly.offset_min, "offset_max"_a = poly.offset_max, "seed"_a = 1,
      py::call_guard<py::gil_scoped_release>(),
      "Sphere cut by random planes (Hu et al. 2023; `clumpkit shape polyhedron`), stretched "
      "to E = I/L and F = S/I, scaled to the volume-equivalent diameter");
  m.def(
      "ellipsoid",
      [](std::array<double, 3> axes, int level) {
        return make_ellipsoid(Vec3(axes[0], axes[1], axes[2]), level);
      },
      "axes"_a, "level"_a = 4, "Ellipsoid of semi-axes (a, b, c) centred at the origin");
  m.def(
      "box", [](std::array<double, 3> size) { return make_box(Vec3(size[0], size[1], size[2])); },
      "size"_a, "Axis-aligned box of edge lengths (x, y, z) centred at the origin");
  m.def("cylinder", &make_cylinder, "diameter"_a, "height"_a, "sides"_a = 64,
        "Prism over a regular polygon inscribed in the circle, along z, centred at the origin");
}

// Shape descriptors.
void bind_descriptors(py::module_& m) {
  py::class_<Descriptors>(m, "Descriptors", "Every shape descriptor of a mesh (its units)")
      .def_readonly("volume", &Descriptors::volume)
      .def_readonly("area", &Descriptors::area)
      .def_readonly("sphericity", &Descriptors::sphericity, "Wadell: π^(1/3) (6V)^(2/3) / A")
      .def_readonly("equivalent_diameter", &Descriptors::equivalent_diameter, "(6V/π)^(1/3)")
      .def_readonly("L", &Descriptors::L, "Caliper length (Jin et al. 2017 §1.1)")
      .def_readonly("W", &Descriptors::W, "Caliper width")
      .def_readonly("H", &Descriptors::H, "Caliper height")
      .def_property_readonly(
          "axes", [](const Descriptors& d) { return array_of(d.axes); },
          "Principal-axis lengths (S, I, L)")
      .def_readonly("E", &Descriptors::E, "I/L (Hu et al. 2023)")
      .def_readonly("F", &Descriptors::F, "S/I")
      .def_readonly("AR", &Descriptors::AR, "S/L")
      .def_readonly("convexity", &Descriptors::convexity, "V / V_hull")
      .def_property_readonly(
          "weighted_roundness", [](const Descriptors& d) { return d.roundness.weighted; },
          "Weighted roundness of Zhang & Zhou 2015")
      .def_property_readonly(
          "view_roundness",
          [](const Descriptors& d) {
            return array_of(Vec3(d.roundness.view[0], d.roundness.view[1], d.roundness.view[2]));
          },
          "Roundness of the views along the S, I, L axes")
      .def(
          "as_dict", [](const Descriptors& d) { return python_of(to_json(d)); },
          "The descriptors as `clumpkit describe --json` names them")
      .def("__repr__",
           [](const Descriptors& d) { return "<clumpkit.Descriptors " + to_json(d).dump() + ">"; });
  m.def("describe", &describe, "mesh"_a, py::call_guard<py::gil_scoped_release>(),
        "Every descriptor of a closed mesh (the GIL released: other Python threads run)");
}

// The fill and its fidelity.
void bind_fill(py::module_& m) {
  py::class_<Fidelity> fidelity(m, "Fidelity",
                                "How faithful a clump is to its mesh (units of the mesh)");
  for_each_fidelity_field(
      [&](const char* name, auto member) { fidelity.def_readonly(name, member); });
  fidelity.def(
      "as_dict", [](const Fidelity& f) { return python_of(fidelity_json(f)); },
      "The record as `clumpkit fill --json` names it");

  py::class_<SolidFill>(m, "Clump", "A clump of overlapping spheres made by fill")
      .def_property_readonly(
          "centres",
          [](const SolidFill& c) {
            std::vector<Vec3> p;
            for (const Sphere& s : c.fill.clump.spheres) p.push_back(s.center);
            return array_of(p);
          },
          "(n, 3) float64 sphere centres")
      .def_property_readonly(
          "radii",
          [](const SolidFill& c) {
            const auto& s = c.fill.clump.spheres;
            py::array_t<double> a(static_cast<py::ssize_t>(s.size()));
            for (std::size_t i = 0; i < s.size(); ++i) a.mutable_data()[i] = s[i].radius;
            return a;
          },
          "(n,) float64 sphere radii")
      .def_property_readonly(
          "coverage_curve",
          [](const SolidFill& c) {
            const auto& v = c.fill.coverage_curve;
            return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
          },
          "Covered fraction of the interior voxels after each sphere")
      .def_property_readonly("fidelity", [](const SolidFill& c) { return c.fidelity; })
      .def_property_readonly("stopped_by", [](const SolidFill& c) { return c.fill.stopped_by; })
      .def_property_readonly("voxel", [](const SolidFill& c) { return c.fill.voxel; })
      .def("__len__", [](const SolidFill& c) { return c.fill.clump.spheres.size(); })
      .def("__repr__", [](const SolidFill& c) {
        return "<clumpkit.Clump " + std::to_string(c.fill.clump.spheres.size()) +
               " spheres, covered " + std::to_string(c.fidelity.covered_fraction) + ">";
      });

  m.def(
      "fill",
      [](const Mesh& mesh, std::optional<int> spheres, std::optional<double> coverage,
         double min_radius, double max_overshoot, std::optional<int> voxels,
         std::optional<double> voxel_size, std::optional<int> refine_iterations,
         const py::object& progress) {
        // The defaults of `clumpkit fill`: 50 spheres without a coverage target; the default
        // resolution within a voxel budget, an asked one as asked.
        FillOptions o;
        if (spheres && *spheres < 1)
          throw InvalidInput("spheres must be at least 1, got " + std::to_string(*spheres));
        o.spheres = spheres.value_or(0);
        o.coverage = coverage.value_or(0.0);
        o.min_radius = min_radius;
        o.max_overshoot = max_overshoot;
        if (voxels) o.field.voxels = *voxels;
        o.field.max_voxels = voxels ? 0.0 : kDefaultMaxVoxels;
        if (voxel_size) o.field.voxel_size = *voxel_size;
        o.voxels_from_count = !voxels && !voxel_size;  // as the command: a resolution given holds
        if (refine_iterations) o.refine_iterations = *refine_iterations;
        SolidFill out;
        run_interruptible(
            [&](const Interrupter& interrupter) {
              out = fill_solid(
                  mesh, o, "mesh", [](const std::string&) {}, interrupter);
            },
            progress);
        return out;
      },
      "mesh"_a, py::kw_only(), "spheres"_a = py::none(), "coverage"_a = py::none(),
      "min_radius"_a = 0.0, "max_overshoot"_a = 0.01, "voxels"_a = py::none(),
      "voxel_size"_a = py::none(), "refine_iterations"_a = py::none(), "progress"_a = py::none(),
      "Greedy maximal-inscribed-sphere fill (`clumpkit fill`, Zhang & Zhou 2015 §2.3): the same "
      "spheres as the command for the same mesh and options (refine_iterations: its "
      "--refine-iterations); progress(stage, fraction) is "
      "called on this thread; Ctrl-C stops it (KeyboardInterrupt)");
}

// Exact mass properties of a union of spheres.
void bind_volume(py::module_& m) {
  py::class_<UnionMass>(m, "MassProperties",
                        "Exact mass properties of a union of spheres (power diagram)")
      .def_property_readonly("volume", [](const UnionMass& u) { return u.u.mass.volume; })
      .def_property_readonly("mass", [](const UnionMass& u) { return u.density * u.u.mass.volume; })
      .def_property_readonly(
          "area", [](const UnionMass& u) { return u.u.area; }, "Area of the union's boundary")
      .def_property_readonly("centroid",
                             [](const UnionMass& u) { return array_of(u.u.mass.centroid); })
      .def_property_readonly(
          "inertia",
          [](const UnionMass& u) { return array_of(Mat3(u.density * u.u.mass.inertia)); },
          "Inertia tensor about the centroid, density × ∫(r²δ − r rᵀ) dV")
      .def_property_readonly(
          "principal_moments",
          [](const UnionMass& u) { return array_of(Vec3(u.density * u.moments)); },
          "Principal moments, ascending")
      .def_property_readonly(
          "principal_axes", [](const UnionMass& u) { return array_of(u.axes); },
          "Principal axes as columns (right-handed, each with its largest component positive)")
      .def_property_readonly(
          "hidden", [](const UnionMass& u) { return u.u.hidden; },
          "Spheres that add nothing to the union");

  m.def(
      "mass_properties",
      [](const Doubles& centres, const Doubles& radii, double density, const py::object& progress) {
        if (!(density > 0.0) || !std::isfinite(density))
          throw InvalidInput("density must be positive and finite, got " + std::to_string(density));
        const Clump clump = clump_from(centres, radii);
        UnionMass out;
        out.density = density;
        run_interruptible(
            [&](const Interrupter& interrupter) { out.u = union_properties(clump, interrupter); },
            progress);
        out.axes = principal_axes(out.u.mass.inertia, out.moments);
        return out;
      },
      "centres"_a, "radii"_a, "density"_a = 1.0, "progress"_a = py::none(),
      "Exact volume, centroid, inertia tensor and principal frame of the union of the spheres "
      "(`clumpkit volume --method exact`), times the density");

  m.def(
      "volume",
      [](const Doubles& centres, const Doubles& radii, const std::string& method, int slices,
         double pixel, const std::string& rule, double voxel, const py::object& progress) {
        const Clump clump = clump_from(centres, radii);
        VolumeJobOptions o;
        o.method = method;
        o.slices = slices;
        o.pixel = pixel;
        o.rule = rule;
        o.voxel = voxel;
        nlohmann::ordered_json j;
        run_interruptible(
            [&](const Interrupter& interrupter) {
              j = measure_volume(clump, o, "the spheres", interrupter);
            },
            progress);
        return method == "all" ? python_of(j) : python_of(j.begin().value());
      },
      "centres"_a, "radii"_a, "method"_a = "exact", py::kw_only(), "slices"_a = 100,
      "pixel"_a = 0.0, "rule"_a = "touch", "voxel"_a = 0.0, "progress"_a = py::none(),
      "Volume of the union by `clumpkit volume`'s methods (exact, inclusion-exclusion, "
      "analytic-slice, pixel-slice, voxel): a dict of what the method gives, as `volume "
      "--json` names it; method='all' gives a dict keyed by method");
}

}  // namespace

// The geometry half of the module: meshes and shapes, descriptors, the fill, exact volumes.
void bind_geometry(py::module_& m) {
  bind_meshes(m);
  bind_descriptors(m);
  bind_fill(m);
  bind_volume(m);
}

}  // namespace clumpkit::python
