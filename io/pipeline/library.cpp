#include "io/pipeline/library.h"

#include "geom/descriptors/descriptors.h"
#include "geom/errors.h"
#include "geom/fill/fidelity.h"
#include "geom/fill/fill.h"
#include "geom/format.h"
#include "geom/template/clump_template.h"
#include "io/base/atomic_file.h"
#include "io/base/json_file.h"
#include "io/base/text.h"
#include "io/base/units.h"
#include "io/formats/clump_io.h"
#include "io/formats/clump_vtp.h"
#include "io/formats/descriptor_table.h"
#include "io/formats/library_table.h"
#include "io/formats/mesh_io.h"
#include "io/pipeline/manifest.h"
#include "io/pipeline/output_dir.h"
#include "io/pipeline/particle_runner.h"
#include "io/pipeline/particle_shape.h"
#include "io/reports/views.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace clumpkit {

namespace {

// The repair of mesh fractions' files, when asked for.
const RepairOptions* repair_of(const LibraryOptions& options) {
  return options.repair ? &options.repair_options : nullptr;
}

// The memory one fill may use: the budget shared by the fills running at once.
double fill_memory_share(const LibraryOptions& options) {
  if (!(options.max_memory_bytes > 0)) return 0.0;
  return options.max_memory_bytes / std::max(1, tbb::this_task_arena::max_concurrency());
}

// Refuses, before any output exists, a recipe whose first particle of some fraction would fill
// beyond its memory share (the particles of a fraction share their resolution and proportions,
// so the first stands for the rest; a later one beyond it is refused when its turn comes).
void check_fill_memory(const ShapeRecipe& recipe, const std::vector<int>& fraction_of,
                       const LibraryOptions& options) {
  const double share = fill_memory_share(options);
  if (share <= 0) return;
  std::vector<char> seen(recipe.fractions.size(), 0);
  for (std::size_t i = 0; i < fraction_of.size(); ++i) {
    if (seen[fraction_of[i]]) continue;
    seen[fraction_of[i]] = 1;
    const GeneratedShape shape =
        particle_shape(recipe, i, fraction_of[i], repair_of(options)).shape;
    const double need =
        fill_bytes_estimate(shape.mesh, fill_field_options(shape.mesh, recipe.fill));
    if (!(need <= share))
      throw InvalidInput(
          "fraction " + recipe.fractions[fraction_of[i]].name + ": the fill of particle " +
          std::to_string(i) + " would need an estimated " + format_number(need / 1073741824.0, 3) +
          " GiB, more than its share of --max-memory (" + format_number(share / 1073741824.0, 3) +
          " GiB per thread): lower fill.voxels or use fewer --threads");
  }
}

// The pictures and ParaView files asked for, from the particles' written files: each made only
// if missing (a resumed run makes what it lacks), then the contact sheet. Particles in
// parallel; every pixel is on its own ray, so the bytes do not depend on the thread count.
void write_pictures(const fs::path& out, const std::vector<nlohmann::ordered_json>& records,
                    const LibraryOptions& options) {
  if (!options.png && !options.vtp) return;
  const fs::path parts = out / "particles";
  const int thumb = 200;
  std::vector<SheetTile> tiles(records.size());
  tbb::parallel_for(std::size_t(0), records.size(), [&](std::size_t i) {
    const std::string stem = id_name(i);
    const fs::path png = parts / (stem + ".png"), vtp = parts / (stem + ".vtp");
    const Mesh mesh = read_mesh_raw((parts / (stem + ".stl")).string());
    const Clump clump = read_clump((parts / (stem + ".csv")).string());
    const auto& f = records[i]["fidelity"];
    if (options.vtp && !fs::exists(vtp)) write_clump_vtp(vtp.string(), mesh, clump);
    if (!options.png) return;
    const ClumpRenderer renderer(mesh, clump);  // one set of Embree scenes for both pictures
    if (!fs::exists(png))
      write_particle_png(
          png.string(), renderer,
          "particle " + stem + " (" + records[i]["fraction"].get<std::string>() +
              "): " + std::to_string(f["spheres"].get<int>()) + " spheres, coverage " +
              format_fixed(f["covered_fraction"].get<double>(), 3) + ", overshoot " +
              format_fixed(f["overshoot_fraction"].get<double>(), 4) + " of the volume");
    tiles[i].image = render_oblique(renderer, thumb);
    tiles[i].label = stem + "  " + std::to_string(f["spheres"].get<int>()) + " sph";
  });
  if (options.png)
    write_contact_sheet((out / "contact_sheet.png").string(),
                        "clumpkit library: " + std::to_string(records.size()) +
                            " particles, oblique views (mesh translucent, spheres coloured)",
                        tiles);
}

// One particle, start to finish; returns its record (also written as NNNNN.json).
nlohmann::ordered_json make_particle(const ShapeRecipe& recipe, std::size_t i, int fraction,
                                     const fs::path& dir, const LibraryOptions& options) {
  const FractionSpec& spec = recipe.fractions[fraction];
  const ParticleShape particle = particle_shape(recipe, i, fraction, repair_of(options));
  const GeneratedShape& shape = particle.shape;
  const Descriptors desc = describe(shape.mesh);
  FillOptions fill_options = recipe.fill;
  fill_options.field.max_bytes = fill_memory_share(options);
  // The voxel the field would derive from the principal extents, which describe() has just
  // computed (the same number: the moments of a scan-sized mesh are not free).
  if (!(fill_options.field.voxel_size > 0.0) && !fill_options.field.vote_sign)
    fill_options.field.voxel_size = desc.axes(0) / fill_options.field.voxels;
  validate(fill_options);
  // One search tree serves the field, the fill and the fidelity (every mesh here is closed:
  // generated, or read as a solid).
  const MeshIndex index(shape.mesh);
  const FillResult filled =
      fill(index, make_distance_field(index, fill_field_options(shape.mesh, fill_options)),
           fill_options);
  if (filled.clump.spheres.empty())
    throw InvalidInput("no sphere fits (fill.min_radius " + format_number(recipe.fill.min_radius) +
                       ")");
  const Fidelity fid = assess_fidelity(index, filled.clump, filled.voxel);

  const ClumpTemplate tpl = make_clump_template(filled.clump, desc.volume);

  const std::string stem = id_name(i);
  const LengthUnit length = si_length();
  write_mesh((dir / (stem + ".stl")).string(), shape.mesh);
  write_clump((dir / (stem + ".csv")).string(), filled.clump,
              "clumpkit library particle " + stem + " (" + spec.name + ")", length.symbol);
  write_clump(
      (dir / (stem + ".template.csv")).string(), Clump{tpl.spheres},
      "clumpkit library particle " + stem +
          ": spheres in the principal frame (centroid at origin)\n"
          "pose to the mesh frame: x = q x' + p, q (w,x,y,z) = " +
          format_number(tpl.orientation.w()) + "," + format_number(tpl.orientation.x()) + "," +
          format_number(tpl.orientation.y()) + "," + format_number(tpl.orientation.z()) +
          ", p = " + format_number(tpl.position.x()) + "," + format_number(tpl.position.y()) + "," +
          format_number(tpl.position.z()) + " " + length.pow(1) +
          "\nunit-density principal moments " + format_number(tpl.principal_moments[0]) + "," +
          format_number(tpl.principal_moments[1]) + "," + format_number(tpl.principal_moments[2]) +
          " " + length.pow(5) + "; volume " + format_number(tpl.mass.volume) + " " + length.pow(3) +
          "; density factor V_mesh/V_clump " + format_number(tpl.density_factor),
      length.symbol);

  nlohmann::ordered_json rec;
  rec["id"] = i;
  rec["fraction"] = spec.name;
  rec["method"] = spec.method;
  if (!particle.source.empty()) rec["source"] = particle.source;
  if (!particle.repair.is_null()) rec["repair"] = particle.repair;
  rec["attempts"] = shape.attempts;
  auto& params = rec["parameters"] = nlohmann::ordered_json::object();
  for (const auto& [name, v] : shape.sampled) params[name] = v;
  auto& d = rec["descriptors"] = nlohmann::ordered_json::object();
  const auto names = descriptor_csv_columns();
  const auto values = descriptor_csv_values(desc);
  for (std::size_t k = 0; k < names.size(); ++k) d[names[k]] = values[k];
  const double fv[] = {double(fid.spheres),    fid.clump_volume,          fid.covered_fraction,
                       fid.overshoot_fraction, fid.surface_mean_distance, fid.surface_max_distance,
                       fid.centroid_offset,    fid.inertia_error,         fid.overshoot_depth_max};
  auto& f = rec["fidelity"] = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < library_fidelity_columns().size(); ++k)
    f[library_fidelity_columns()[k]] = fv[k];
  f["clump_volume_method"] = fid.clump_volume_method;
  f["voxel"] = filled.voxel;
  f["stopped_by"] = filled.stopped_by;
  // `f` is no reference into `rec` past this point: an ordered_json keeps its members in a
  // vector, which the next member may move.
  auto& t = rec["template"] = nlohmann::ordered_json::object();
  t["volume"] = tpl.mass.volume;
  t["centroid"] = {tpl.position.x(), tpl.position.y(), tpl.position.z()};
  t["principal_moments"] = {tpl.principal_moments[0], tpl.principal_moments[1],
                            tpl.principal_moments[2]};
  t["orientation_wxyz"] = {tpl.orientation.w(), tpl.orientation.x(), tpl.orientation.y(),
                           tpl.orientation.z()};
  t["density_factor"] = tpl.density_factor;
  t["spheres_file"] = "particles/" + stem + ".template.csv";
  add_units(rec, length);
  write_sealed_record((dir / (stem + ".json")).string(), rec);
  return rec;
}

}  // namespace

LibraryResult run_library(const ShapeRecipe& recipe, const std::string& out_dir,
                          const LibraryOptions& options, const Interrupter& interrupter) {
  // The output-directory rule of every job (job.h): work in DIR.partial, rename at the end. A
  // DIR.partial of the same recipe is a killed run's work and is resumed; one of another
  // recipe is stale and starts afresh.
  check_output_directory(out_dir);
  const std::vector<int> fraction_of = particle_fractions(recipe);
  check_fill_memory(recipe, fraction_of, options);
  const fs::path out = out_dir + ".partial", parts = out / "particles";
  const fs::path stamp = out / "recipe.toml";
  std::error_code ec;
  if (fs::exists(out) && !(fs::exists(stamp) && read_file(stamp.string()) == recipe.text))
    fs::remove_all(out, ec);
  remove_stray_temporaries(out.string());  // a killed run's half-written files
  fs::create_directories(parts, ec);
  if (ec) throw IoError(out.string() + ": cannot create directory: " + ec.message());
  write_file_atomically(stamp.string(), [&](std::ostream& o) { o << recipe.text; });

  const std::size_t total = fraction_of.size();

  std::vector<nlohmann::ordered_json> records(total);
  std::vector<char> todo(total, 1);
  LibraryResult result;
  result.particles = total;
  result.out_dir = out_dir;
  for (std::size_t i = 0; i < total; ++i) {
    const fs::path rec = parts / (id_name(i) + ".json");
    if (!fs::exists(rec)) continue;
    // A record that does not parse or fails its checksum is redone and reported, never used.
    if (read_sealed_record(rec.string(), records[i])) {
      todo[i] = 0;
      ++result.resumed;
      continue;
    }
    result.redone.push_back("particles/" + id_name(i) + ".json");
  }

  try {
    for_each_particle(
        recipe, fraction_of, todo, result.resumed,
        [&](std::size_t i) {
          records[i] = make_particle(recipe, i, fraction_of[i], parts, options);
        },
        "library", interrupter);
  } catch (const Interrupted& e) {
    throw Interrupted(std::string(e.what()) + "; the finished ones are kept in " + out.string() +
                      " for a rerun");
  }

  write_library_table((out / "library.csv").string(), records);

  write_pictures(out, records, options);

  nlohmann::ordered_json m = manifest_head("library", recipe);
  m["units_note"] = "clumps are x,y,z,r in the mesh frame";
  auto& fill = m["fill"];
  fill["spheres"] = recipe.fill.spheres;
  fill["coverage"] = recipe.fill.coverage;
  fill["min_radius"] = recipe.fill.min_radius;
  fill["voxels"] = recipe.fill.field.voxels;
  fill["max_overshoot"] = recipe.fill.max_overshoot;
  double cov = 0, over = 0, spheres = 0;
  for (const auto& rec : records) {
    cov += rec["fidelity"]["covered_fraction"].get<double>();
    over += rec["fidelity"]["overshoot_fraction"].get<double>();
    spheres += rec["fidelity"]["spheres"].get<double>();
  }
  if (total > 0) {
    m["mean_covered_fraction"] = cov / total;
    m["mean_overshoot_fraction"] = over / total;
    m["mean_spheres"] = spheres / total;
  }
  auto& fr = m["fractions"] = nlohmann::ordered_json::array();
  std::size_t first = 0;
  for (const auto& f : recipe.fractions) {
    fr.push_back({{"name", f.name}, {"method", f.method}, {"count", f.count}, {"first_id", first}});
    first += f.count;
  }
  add_units(m, si_length());
  write_file_atomically((out / "manifest.json").string(),
                        [&](std::ostream& o) { o << m.dump(2) << "\n"; });
  publish_directory(out.string(), out_dir);
  return result;
}

}  // namespace clumpkit
