// Bindings of the jobs: reading a built specimen into arrays, and the library and specimen
// pipelines of the command line.
#include "geom/errors.h"
#include "io/formats/specimen_csv.h"
#include "io/pipeline/library.h"
#include "io/pipeline/specimen.h"
#include "io/pipeline/threads.h"
#include "io/recipes/recipe.h"
#include "io/recipes/specimen_recipe.h"
#include "python/src/arrays.h"
#include "python/src/run.h"

#include <pybind11/stl.h>

#include <filesystem>
#include <memory>

namespace py = pybind11;
using namespace py::literals;

namespace clumpkit::python {

namespace {

template <class T>
py::array_t<T> column(std::size_t n) {
  return py::array_t<T>(static_cast<py::ssize_t>(n));
}

template <class T>
py::array_t<T> table(std::size_t n, int width) {
  return py::array_t<T>({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(width)});
}

}  // namespace

void bind_pipelines(py::module_& m) {
  m.def(
      "read_specimen",
      [](const std::string& path) {
        namespace fs = std::filesystem;
        const std::string file =
            fs::is_directory(path) ? (fs::path(path) / "specimen.csv").string() : path;
        const std::vector<SpecimenBody> bodies = read_specimen_csv(file);
        const std::size_t n = bodies.size();
        std::size_t spheres = 0;
        for (const SpecimenBody& b : bodies) spheres += b.spheres.size();
        auto id = column<long long>(n), templ = column<long long>(n), zone = column<long long>(n);
        auto rock = column<bool>(n);
        auto mass = column<double>(n), volume = column<double>(n), scale = column<double>(n);
        auto position = table<double>(n, 3), moments = table<double>(n, 3);
        auto quaternion = table<double>(n, 4);
        auto sphere_body = column<long long>(spheres);
        auto centres = table<double>(spheres, 3);
        auto radii = column<double>(spheres);
        std::size_t k = 0;
        for (std::size_t i = 0; i < n; ++i) {
          const SpecimenBody& b = bodies[i];
          id.mutable_data()[i] = b.id;
          templ.mutable_data()[i] = b.template_id;
          zone.mutable_data()[i] = b.zone;
          rock.mutable_data()[i] = b.kind == dem::BodyKind::rock;
          mass.mutable_data()[i] = b.mass;
          volume.mutable_data()[i] = b.volume;
          scale.mutable_data()[i] = b.scale;
          const double q[4] = {b.orientation.w(), b.orientation.x(), b.orientation.y(),
                               b.orientation.z()};
          for (int c = 0; c < 3; ++c) {
            position.mutable_data()[3 * i + c] = b.position[c];
            moments.mutable_data()[3 * i + c] = b.moments[c];
          }
          for (int c = 0; c < 4; ++c) quaternion.mutable_data()[4 * i + c] = q[c];
          for (const Sphere& s : b.spheres) {
            sphere_body.mutable_data()[k] = b.id;
            for (int c = 0; c < 3; ++c) centres.mutable_data()[3 * k + c] = s.center[c];
            radii.mutable_data()[k] = s.radius;
            ++k;
          }
        }
        py::dict out;
        out["id"] = id;
        out["rock"] = rock;
        out["template"] = templ;
        out["position"] = position;
        out["quaternion"] = quaternion;
        out["mass"] = mass;
        out["volume"] = volume;
        out["scale"] = scale;
        out["moments"] = moments;
        out["zone"] = zone;
        out["sphere_body"] = sphere_body;
        out["sphere_centres"] = centres;
        out["sphere_radii"] = radii;
        return out;
      },
      "path"_a,
      "The bodies and spheres of a built specimen (its folder or its specimen.csv) as arrays, "
      "SI: per body id (from 1), rock (bool; soil otherwise), template (library particle, -1 "
      "for soil), position (n, 3: centroid), quaternion (n, 4: w, x, y, z, body → world), "
      "mass, volume, scale, moments (n, 3: principal, about the body axes), zone; per sphere "
      "sphere_body (the body's id), sphere_centres (k, 3: world frame), sphere_radii");

  m.def(
      "library",
      [](const std::string& recipe, const std::string& out, bool png, bool vtp, int threads,
         const py::object& progress) {
        const ShapeRecipe r = read_shape_recipe(recipe);
        LibraryOptions o;
        o.png = png;
        o.vtp = vtp;
        LibraryResult result;
        const auto limit = limit_threads(threads);
        run_interruptible(
            [&](const Interrupter& interrupter) { result = run_library(r, out, o, interrupter); },
            progress);
        py::dict d;
        d["particles"] = result.particles;
        d["resumed"] = result.resumed;
        d["redone"] = result.redone;
        d["out"] = result.out_dir;
        return d;
      },
      "recipe"_a, "out"_a, py::kw_only(), "png"_a = false, "vtp"_a = false, "threads"_a = kAllCores,
      "progress"_a = py::none(),
      "`clumpkit library`: the clump library of a shape recipe in the folder `out` (written in "
      "out.partial; a stopped run called again resumes it to the same bytes); returns "
      "particles, resumed, redone and out");

  m.def(
      "specimen",
      [](const std::string& recipe, const std::string& out, bool resume, int threads,
         const py::object& progress) {
        const SpecimenRecipe r = read_specimen_recipe(recipe);
        SpecimenJobOptions o;
        o.resume = resume;
        nlohmann::ordered_json report;
        const auto limit = limit_threads(threads);
        run_interruptible(
            [&](const Interrupter& interrupter) {
              report = run_specimen(r, out, o, interrupter).report;
            },
            progress);
        return python_of(report);
      },
      "recipe"_a, "out"_a, py::kw_only(), "resume"_a = false, "threads"_a = kAllCores,
      "progress"_a = py::none(),
      "`clumpkit specimen`: builds the specimen of a recipe into the folder `out` and returns "
      "its report.json as a dict; stopped (Ctrl-C), it keeps out.partial with its checkpoints "
      "and resume=True goes on from there");
}

}  // namespace clumpkit::python
