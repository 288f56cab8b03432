// `clumpkit shape <block|hull|polyhedron|ellipsoid|cylinder|box>`: one particle to a mesh file.
#include "geom/descriptors/descriptors.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "geom/shapes/block.h"
#include "geom/shapes/hull.h"
#include "geom/shapes/polyhedron.h"
#include "geom/shapes/primitives.h"
#include "io/base/units.h"
#include "io/cli/common.h"
#include "io/formats/descriptor_table.h"
#include "io/formats/mesh_io.h"

#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

namespace {

struct Common {
  std::string out, length_unit = "L";
  std::uint64_t seed = 1;
  bool json = false;
};

void add_common(CLI::App* c, Common& o, bool seeded) {
  c->add_option("-o,--output", o.out, "Output mesh (.stl, .obj or .ply)")->required();
  if (seeded) c->add_option("--seed", o.seed, "Random seed")->capture_default_str();
  c->add_flag("--json", o.json, "Print the descriptors of the result as JSON on stdout");
  add_length_unit_option(c, o.length_unit,
                         "The length unit of the lengths given here, e.g. mm: only labels the "
                         "output (default L, the unit they are in)");
}

void finish(const Mesh& mesh, const Common& o, nlohmann::json extra = {}) {
  const LengthUnit length = length_unit(o.length_unit);
  const Descriptors d = describe(mesh);
  write_mesh(o.out, mesh);
  if (o.json) {
    nlohmann::json j = to_json(d);
    j["file"] = o.out;
    j["triangles"] = mesh.triangles.size();
    for (auto& [k, v] : extra.items()) j[k] = v;
    nlohmann::ordered_json out = j;
    add_units(out, length);
    std::cout << out.dump(2) << "\n";
  } else {
    std::printf(
        "wrote %s: %zu triangles, volume %s %s, L x W x H %s x %s x %s %s, sphericity %.4f, "
        "weighted roundness %.4f\n",
        o.out.c_str(), mesh.triangles.size(), format_number(d.volume).c_str(),
        length.pow(3).c_str(), format_number(d.L).c_str(), format_number(d.W).c_str(),
        format_number(d.H).c_str(), length.symbol.c_str(), d.sphericity, d.roundness.weighted);
    for (auto& [k, v] : extra.items()) std::printf("  %s: %s\n", k.c_str(), v.dump().c_str());
  }
}

Vec3 parse_triple(const std::vector<double>& v, const char* field) {
  if (v.size() != 3)
    throw InvalidInput(std::string(field) + ": expected three comma-separated numbers, got " +
                       std::to_string(v.size()));
  return Vec3(v[0], v[1], v[2]);
}

}  // namespace

void register_shape(CLI::App& app) {
  auto* shape = app.add_subcommand("shape", "Generate one particle and write it as a mesh");
  shape->require_subcommand(1);

  {
    auto o = std::make_shared<Common>();
    auto p = std::make_shared<BlockParams>();
    auto* c = shape->add_subcommand(
        "block",
        "Rock block of Jin et al. 2017 §2.1: cuboid L x W x H (x, y, z), edges split in Nd, node "
        "radii scaled by U(Sl, Su). Lengths in any unit; the mesh keeps it.");
    c->add_option("--L", p->L, "Length (x)")->required();
    c->add_option("--W", p->W, "Width (y)")->required();
    c->add_option("--H", p->H, "Height (z)")->required();
    c->add_option("--nd", p->nd, "Segments per cuboid edge Nd")->capture_default_str();
    c->add_option("--sl", p->sl, "Lower radial scale factor Sl")->capture_default_str();
    c->add_option("--su", p->su, "Upper radial scale factor Su")->capture_default_str();
    add_common(c, *o, true);
    c->callback([o, p] {
      Rng rng(o->seed);
      finish(make_block(*p, rng), *o);
    });
  }
  {
    auto o = std::make_shared<Common>();
    auto p = std::make_shared<HullParams>();
    auto band = std::make_shared<std::string>("1:10");
    auto* c = shape->add_subcommand(
        "hull",
        "Random convex hull of Zhang & Zhou 2015 §2.1: N points on a sphere of diameter d, redrawn "
        "until the weighted roundness is in the band");
    c->add_option("--diameter", p->diameter, "Sphere diameter d")->required();
    c->add_option("--points", p->points, "Number of random points N")->capture_default_str();
    c->add_option("--roundness", *band, "Weighted roundness band MIN:MAX")->capture_default_str();
    c->add_option("--aspect-min", p->aspect_min,
                  "Smallest flattening drawn per attempt (1 = points on the sphere only)")
        ->capture_default_str();
    c->add_option("--max-attempts", p->max_attempts, "Attempts before giving up")
        ->capture_default_str();
    add_common(c, *o, true);
    c->callback([o, p, band] {
      const auto colon = band->find(':');
      try {
        if (colon == std::string::npos) throw std::invalid_argument("no colon");
        std::size_t n1 = 0, n2 = 0;
        p->roundness_min = std::stod(band->substr(0, colon), &n1);
        p->roundness_max = std::stod(band->substr(colon + 1), &n2);
        if (n1 != colon || n2 != band->size() - colon - 1) throw std::invalid_argument("trailing");
      } catch (const std::logic_error&) {
        throw InvalidInput("--roundness: expected MIN:MAX, got '" + *band + "'");
      }
      Rng rng(o->seed);
      HullResult r = make_hull(*p, rng);
      finish(r.mesh, *o, {{"attempts", r.attempts}});
    });
  }
  {
    auto o = std::make_shared<Common>();
    auto p = std::make_shared<PolyhedronParams>();
    auto* c = shape->add_subcommand(
        "polyhedron",
        "Sphere cut by random planes (Hu et al. 2023), stretched to E = I/L and F = S/I, "
        "scaled to volume-equivalent diameter D");
    c->add_option("--diameter", p->diameter, "Volume-equivalent diameter D")->required();
    c->add_option("--planes", p->planes, "Number of random cutting planes")->capture_default_str();
    c->add_option("--E", p->E, "Elongation I/L, in (0, 1]")->capture_default_str();
    c->add_option("--F", p->F, "Flatness S/I, in (0, 1]")->capture_default_str();
    c->add_option("--offset-min", p->offset_min, "Smallest plane distance / sphere radius")
        ->capture_default_str();
    c->add_option("--offset-max", p->offset_max, "Largest plane distance / sphere radius")
        ->capture_default_str();
    add_common(c, *o, true);
    c->callback([o, p] {
      Rng rng(o->seed);
      finish(make_polyhedron(*p, rng), *o);
    });
  }
  {
    auto o = std::make_shared<Common>();
    auto axes = std::make_shared<std::vector<double>>();
    auto level = std::make_shared<int>(4);
    auto* c = shape->add_subcommand("ellipsoid",
                                    "Ellipsoid (subdivided icosphere) centred at the origin");
    c->add_option("--axes", *axes, "Semi-axes a,b,c along x,y,z")->required()->delimiter(',');
    c->add_option("--level", *level, "Subdivision level (20*4^level triangles)")
        ->capture_default_str();
    add_common(c, *o, false);
    c->callback(
        [o, axes, level] { finish(make_ellipsoid(parse_triple(*axes, "--axes"), *level), *o); });
  }
  {
    auto o = std::make_shared<Common>();
    auto d = std::make_shared<double>(0.0), h = std::make_shared<double>(0.0);
    auto sides = std::make_shared<int>(64);
    auto* c = shape->add_subcommand(
        "cylinder",
        "Cylinder (a prism over a regular polygon inscribed in the circle) along z, centred at "
        "the origin; e.g. the Brazilian disc of Hu et al. 2023: --diameter 0.05 --height 0.05");
    c->add_option("--diameter", *d, "Diameter of the circle through the polygon's corners")
        ->required();
    c->add_option("--height", *h, "Height along z")->required();
    c->add_option("--sides", *sides, "Sides of the polygon, at least 3")->capture_default_str();
    add_common(c, *o, false);
    c->callback([o, d, h, sides] { finish(make_cylinder(*d, *h, *sides), *o); });
  }
  {
    auto o = std::make_shared<Common>();
    auto size = std::make_shared<std::vector<double>>();
    auto* c = shape->add_subcommand("box", "Axis-aligned box centred at the origin");
    c->add_option("--size", *size, "Edge lengths x,y,z")->required()->delimiter(',');
    add_common(c, *o, false);
    c->callback([o, size] { finish(make_box(parse_triple(*size, "--size")), *o); });
  }
}

}  // namespace clumpkit::cli
