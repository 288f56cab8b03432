// A library's or shape set's page data: its table, each particle's mesh and spheres for the 3-D
// view (parts/NNNNN.js), its renders.
#include "geom/errors.h"
#include "geom/mesh/mesh_index.h"
#include "geom/mesh/ray_inside.h"
#include "geom/mesh/sphere_reach.h"
#include "io/base/units.h"
#include "io/formats/clump_io.h"
#include "io/formats/mesh_io.h"
#include "io/pipeline/page_data.h"

namespace clumpkit::page_data {

namespace {

// A sphere "reaches outside" its mesh when it pokes through the surface by more than this share
// of its radius: the fill's spheres touch the surface from inside up to the voxel size and the
// overshoot contract, which reach a few percent of a radius; a tenth is a sphere to look at.
constexpr double kOutside = 0.1;

// A particle for the 3-D view: its mesh, its spheres with whether each reaches outside the mesh
// (kOutside) and by how much (share of its radius), and its bounds. Returns the count of such
// spheres.
int particle_json(const fs::path& mesh_path, const fs::path& clump_path, ordered_json& part) {
  const Mesh mesh = read_mesh(mesh_path.string());
  ordered_json v = ordered_json::array(), f = ordered_json::array(), s = ordered_json::array();
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Vec3& x : mesh.vertices) {
    for (int k = 0; k < 3; ++k) v.push_back(sig(x[k]));
    lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  }
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) f.push_back(t[k]);
  int outside = 0;
  if (!clump_path.empty()) {
    const Clump clump = read_clump(clump_path.string());
    const MeshIndex index(mesh);
    const RayInside in(mesh);
    for (const Sphere& sp : clump.spheres) {
      const double reach = sphere_reach(index, in, sp);
      const bool out = reach > kOutside * sp.radius;
      outside += out ? 1 : 0;
      s.push_back({sig(sp.center.x()), sig(sp.center.y()), sig(sp.center.z()), sig(sp.radius),
                   out ? 1 : 0, sig(reach / sp.radius)});
      lo = lo.cwiseMin(sp.center - Vec3::Constant(sp.radius));
      hi = hi.cwiseMax(sp.center + Vec3::Constant(sp.radius));
    }
  }
  part = {{"v", v},
          {"f", f},
          {"s", s},
          {"lo", {lo.x(), lo.y(), lo.z()}},
          {"hi", {hi.x(), hi.y(), hi.z()}}};
  return outside;
}

}  // namespace

std::size_t library_data(const Folder& f, const fs::path& out, ordered_json& data,
                         std::vector<PageScript>& scripts) {
  const bool shapes = f.command == "shapes";
  const fs::path table = f.dir / (shapes ? "shapes.csv" : "library.csv");
  CsvTable t = read_table(table);
  const int id = t.column("id"), mesh = t.column("mesh"), clump = t.column("clump");
  if (id < 0 || mesh < 0) throw InvalidInput(table.string() + ": columns id and mesh are required");
  t.columns.push_back("outside");
  t.units.push_back(kDimensionless);  // a count of spheres
  Images images{out, &scripts};
  images.add(f.dir / "contact_sheet.png", "contact sheet");
  for (auto& row : t.rows) {
    if (!row[static_cast<std::size_t>(id)].is_number())
      throw InvalidInput(f.dir.string() + ": a particle id is not a number");
    const fs::path m = f.dir / row[static_cast<std::size_t>(mesh)].get<std::string>();
    const fs::path c =
        clump >= 0 ? f.dir / row[static_cast<std::size_t>(clump)].get<std::string>() : fs::path();
    ordered_json part;
    row.emplace_back(particle_json(m, c, part));
    const std::string name = id_stem(row[static_cast<std::size_t>(id)], table);
    // The page loads it when its row is clicked (clumpkit_part, assets/page/library.js).
    scripts.push_back({"parts/" + name + ".js", "clumpkit_part(" + part.dump() + ");\n"});
    images.add(fs::path(m).replace_extension(".png"), "particle " + name);
  }
  data["table"] =
      table_json(t, {"id", "fraction", "method", "L", "W", "H", "volume", "equivalent_diameter",
                     "sphericity", "E", "F", "AR", "convexity", "weighted_roundness", "spheres",
                     "covered_fraction", "overshoot_fraction", "surface_max_distance", "outside"});
  data["parts"] = "page/parts/";
  data["images"] = images.list;
  return t.rows.size();
}

}  // namespace clumpkit::page_data
