#include "io/pipeline/export.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/atomic_file.h"
#include "io/base/units.h"
#include "io/export/export_source.h"
#include "io/export/formats.h"
#include "io/pipeline/lab_setup.h"
#include "io/pipeline/manifest.h"
#include "io/pipeline/output_dir.h"
#include "io/recipes/lab_recipe.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace clumpkit {

namespace fs = std::filesystem;

namespace {

// The CPT of `options.cpt_recipe` on the specimen `src`, checked (before anything is written).
LammpsCpt lammps_cpt_of(const ExportOptions& options, const std::string& format,
                        const std::string& source, const ExportSource& src,
                        const std::string& not_specimen) {
  if (format != "lammps")
    throw InvalidInput("export: --test cpt is only available for lammps, not " + format);
  if (src.templates) throw InvalidInput("export: --test cpt tests a specimen" + not_specimen);
  if (options.lammps.tiles_x * options.lammps.tiles_y > 1)
    throw InvalidInput("export: --tile and --test cpt do not go together (one probe, one chamber)");
  const TestRecipe recipe = read_test_recipe(options.cpt_recipe);
  if (!recipe.probe)
    throw InvalidInput(recipe.path +
                       ": probe: --test cpt needs a [probe] section (diameter, apex_deg, "
                       "velocity, depth)");
  LammpsCpt cpt;
  cpt.probe = *recipe.probe;
  const double test_friction =
      recipe.settings.friction >= 0 ? recipe.settings.friction : src.settings.contact.friction;
  if (cpt.probe.friction < 0) cpt.probe.friction = test_friction;
  cpt.confining = recipe.settings.confining;
  cpt.record_every = recipe.settings.record_every;
  check_lammps_cpt(cpt, src.settings, recipe.path);
  const std::string report_path = (fs::path(source) / "report.json").string();
  const double core = radial_core_radius(src.report, report_path);
  try {
    dem::check_probe_core(cpt.probe, core);
  } catch (const InvalidInput& e) {
    throw InvalidInput(recipe.path + ": " + e.what() + " (" + report_path + ")");
  }
  if (src.settings.contact.scaling == dem::StiffnessScaling::linear)
    cpt.classes = stiffness_classes(src.bodies, report_path);
  if (src.settings.segment_angle_deg > 0) {
    std::vector<dem::Body> bodies;
    for (const SpecimenBody& b : src.bodies) bodies.push_back(dem_body(b));
    try {
      dem::check_segment_reach(bodies, Vec3::Zero(), src.settings.segment_angle_deg * M_PI / 180.0,
                               cpt.probe);
    } catch (const InvalidInput& e) {
      throw InvalidInput(recipe.path + ": " + e.what());
    }
  }
  return cpt;
}

}  // namespace

ExportResult run_export(const std::string& format, const std::string& source,
                        const std::string& out_dir, const ExportOptions& options) {
  const ExportFormat* engine = find_export_format(format);
  if (!engine)
    throw InvalidInput("export: unknown format '" + format + "' (one of " + export_format_names() +
                       ")");
  if (options.lammps.oedometer && format != "lammps")
    throw InvalidInput("export: --test oedometer is only available for lammps, not " + format);
  if (options.lammps.oedometer &&
      !(options.lammps.max_strain > 0 && options.lammps.max_strain < 1 &&
        std::isfinite(options.lammps.max_strain)))
    throw InvalidInput("export: --max-strain must be in (0, 1), got " +
                       format_number(options.lammps.max_strain));
  if (options.lammps.oedometer &&
      !(options.lammps.strain_rate > 0 && std::isfinite(options.lammps.strain_rate)))
    throw InvalidInput("export: --strain-rate must be positive (1/s), got " +
                       format_number(options.lammps.strain_rate));
  const int tiles = options.lammps.tiles_x * options.lammps.tiles_y;
  if (options.lammps.tiles_x < 1 || options.lammps.tiles_y < 1 || options.lammps.tiles_x > 1000 ||
      options.lammps.tiles_y > 1000)
    throw InvalidInput("export: --tile must be NXxNY with 1 <= NX, NY <= 1000, got " +
                       std::to_string(options.lammps.tiles_x) + "x" +
                       std::to_string(options.lammps.tiles_y));
  if (tiles > 1 && format != "lammps")
    throw InvalidInput("export: --tile is only available for lammps, not " + format);
  if (tiles > 1 && options.lammps.oedometer)
    throw InvalidInput(
        "export: --tile and --test oedometer do not go together (one platen, "
        "one container)");
  check_output_spares(out_dir, source, "the source");
  ExportSource src = read_export_source(source, options.source);
  std::vector<SpecimenBody>& bodies = src.bodies;
  const EngineSettings& settings = src.settings;
  const std::string not_specimen =
      ", and " + source + " is " + (src.kind == "library" ? "a clump library" : "a clump CSV");
  if (tiles > 1 && src.templates)
    throw InvalidInput("export: --tile copies a specimen" + not_specimen);
  if (options.lammps.oedometer && src.templates)
    throw InvalidInput("export: --test oedometer tests a specimen" + not_specimen);
  LammpsDeck deck = options.lammps;
  if (!options.cpt_recipe.empty())
    deck.cpt = lammps_cpt_of(options, format, source, src, not_specimen);
  // What the other decks cannot carry is refused rather than dropped silently.
  if (settings.segment_angle_deg > 0 && !deck.cpt)
    throw InvalidInput(source +
                       ": container.shape: \"segment\" specimens are exported only as a CPT "
                       "chamber (--test cpt; the other decks model a whole cylinder container): "
                       "export a cylinder specimen");
  if (settings.contact.scaling == dem::StiffnessScaling::linear && !deck.cpt)
    throw InvalidInput((fs::path(source) / "report.json").string() +
                       ": contact.stiffness_scaling: \"linear\" (kn ∝ d) is exported only in "
                       "the LAMMPS CPT deck (--test cpt); the other decks use one kn and ks for "
                       "every contact");
  if (tiles > 1)
    bodies = tile_bodies(bodies, options.lammps.tiles_x, options.lammps.tiles_y,
                         2 * settings.container_radius);

  ExportResult result;
  result.format = format;
  result.bodies = bodies.size();
  for (const SpecimenBody& b : bodies) result.spheres += b.spheres.size();
  std::vector<std::string> written;
  write_staged(out_dir, [&](const std::string& dir) {
    const fs::path staging = dir;
    written = engine->write(src, bodies, staging.string(), deck);
    result.run = engine->run();
    const nlohmann::json& manifest = src.manifest;
    nlohmann::ordered_json m =
        manifest.is_object()
            ? manifest_head("export", manifest.value("recipe_path", std::string()),
                            manifest.value("recipe", std::string()), manifest.value("seed", 0ULL))
            : manifest_head("export", "", "", 0);
    m["format"] = format;
    m["source"] = fs::absolute(source).lexically_normal().string();
    m["source_kind"] = src.kind;
    if (src.templates) {
      m["density"] = options.source.density;
      m["length_unit"] = options.source.length_unit.empty() ? "m" : options.source.length_unit;
      m["mass"] = options.source.mass.empty() ? "clump" : options.source.mass;
    }
    m["bodies"] = result.bodies;
    m["spheres"] = result.spheres;
    m["run"] = result.run;
    if (deck.cpt && !deck.cpt->classes.empty()) {
      nlohmann::ordered_json classes = nlohmann::ordered_json::array();
      for (std::size_t k = 0; k < deck.cpt->classes.size(); ++k) {
        const StiffnessClass& c = deck.cpt->classes[k];
        classes.push_back({{"type", k + 2},
                           {"diameter", c.diameter},
                           {"d_min", c.d_min},
                           {"d_max", c.d_max},
                           {"bodies", c.bodies}});
      }
      m["stiffness_classes"] = classes;
      m["stiffness_class_error"] = stiffness_class_error(deck.cpt->classes);
    }
    if (tiles > 1) m["tiles"] = {options.lammps.tiles_x, options.lammps.tiles_y};
    if (options.lammps.oedometer)
      m["test"] = {{"kind", "oedometer"},
                   {"max_strain", options.lammps.max_strain},
                   {"strain_rate", options.lammps.strain_rate}};
    add_units(m, si_length());
    write_file_atomically((staging / "manifest.json").string(),
                          [&](std::ostream& o) { o << m.dump(2) << "\n"; });
  });
  for (const std::string& f : written)
    result.files.push_back((fs::path(out_dir) / fs::path(f).filename()).string());
  result.files.push_back((fs::path(out_dir) / "manifest.json").string());
  return result;
}

}  // namespace clumpkit
