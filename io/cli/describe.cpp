// `clumpkit describe MESH`: shape descriptors of a closed mesh.
#include "geom/descriptors/descriptors.h"
#include "geom/format.h"
#include "io/base/units.h"
#include "io/cli/common.h"
#include "io/formats/descriptor_table.h"
#include "io/formats/mesh_io.h"

#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

void register_describe(CLI::App& app) {
  struct Opts {
    std::string mesh, length_unit = "L";
    bool json = false;
    MeshReadOptions read;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "describe",
      "Shape descriptors of a closed mesh (STL, OBJ, PLY), in the units of the mesh: volume, "
      "area, Wadell sphericity, volume-equivalent diameter, caliper L W H (Jin et al. 2017 §1.1), "
      "principal-axis lengths S I L (inertia-aligned box) with E F AR (Hu et al. 2023), convexity "
      "V/V_hull, weighted roundness over three principal views (Zhang & Zhou 2015 eq. 2)");
  c->add_option("MESH", o->mesh, "Mesh file")->required();
  c->add_flag("--json", o->json, "Print one JSON object on stdout");
  add_weld_option(c, o->read.weld_tolerance);
  add_length_unit_option(c, o->length_unit);
  c->callback([o] {
    const LengthUnit length = length_unit(o->length_unit);
    MeshReadReport report;
    const Mesh mesh = read_mesh(o->mesh, &report, o->read);
    for (const std::string& line : mesh_read_notes(o->mesh, report)) note(line);
    const Descriptors d = describe(mesh);
    if (o->json) {
      nlohmann::json j = to_json(d);
      j["file"] = o->mesh;
      j["reoriented"] = report.reoriented;
      j["merged_vertices"] = report.merged_vertices;
      j["removed_triangles"] = report.removed_triangles;
      j["shells"] = report.shells;
      nlohmann::ordered_json out = j;
      add_units(out, length);
      std::cout << out.dump(2) << "\n";
      return;
    }
    auto f = [](double v) { return format_number(v); };
    const char* l = length.symbol.c_str();
    std::printf("%s\n", o->mesh.c_str());
    std::printf("  vertices, triangles   %zu, %zu\n", mesh.vertices.size(), mesh.triangles.size());
    std::printf("  volume                %s %s\n", f(d.volume).c_str(), length.pow(3).c_str());
    std::printf("  area                  %s %s\n", f(d.area).c_str(), length.pow(2).c_str());
    std::printf("  sphericity            %.6f\n", d.sphericity);
    std::printf("  equivalent diameter   %s %s\n", f(d.equivalent_diameter).c_str(), l);
    std::printf("  L, W, H               %s, %s, %s %s\n", f(d.L).c_str(), f(d.W).c_str(),
                f(d.H).c_str(), l);
    std::printf("  axes S, I, L          %s, %s, %s %s\n", f(d.axes[0]).c_str(),
                f(d.axes[1]).c_str(), f(d.axes[2]).c_str(), l);
    std::printf("  E, F, AR              %.4f, %.4f, %.4f\n", d.E, d.F, d.AR);
    std::printf("  convexity             %.6f\n", d.convexity);
    std::printf("  weighted roundness    %.6f (views S, I, L: %.4f, %.4f, %.4f)\n",
                d.roundness.weighted, d.roundness.view[0], d.roundness.view[1],
                d.roundness.view[2]);
  });
}

}  // namespace clumpkit::cli
