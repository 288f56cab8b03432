#include "io/pipeline/lab_setup.h"

#include "dem/core/crushable.h"
#include "dem/core/timestep.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "geom/hash.h"
#include "io/base/atomic_file.h"
#include "io/base/json_file.h"
#include "io/base/text.h"
#include "io/base/units.h"
#include "io/formats/bonds_csv.h"
#include "io/formats/specimen_csv.h"
#include "io/pipeline/manifest.h"
#include "io/pipeline/output_dir.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace clumpkit {

namespace fs = std::filesystem;

namespace {

double report_number(const nlohmann::json& j, const std::string& path, const char* a,
                     const char* b) {
  const nlohmann::json* v = j.contains(a) ? &j[a] : nullptr;
  if (v && b) v = v->contains(b) ? &(*v)[b] : nullptr;
  if (!v || !v->is_number() || !std::isfinite(v->get<double>()))
    throw InvalidInput(path + ": field " + a + "." + b + " missing or not a number");
  return v->get<double>();
}

// The contact law: the specimen's, overridden field by field by the recipe.
dem::ContactParams contact_law(const nlohmann::json& report, const std::string& path,
                               const TestRecipe& r) {
  dem::ContactParams c;
  c.kn = report_number(report, path, "contact", "kn");
  c.ks = report_number(report, path, "contact", "ks");
  c.friction = report_number(report, path, "contact", "friction");
  c.damping_ratio = report_number(report, path, "contact", "damping_ratio");
  c.local_damping = report_number(report, path, "contact", "local_damping");
  // The law the specimen was built with (report.json of specimens before 0.x has no rule: none).
  const nlohmann::json& rc = report.at("contact");
  if (rc.contains("stiffness_scaling") && rc["stiffness_scaling"] == "linear") {
    c.scaling = dem::StiffnessScaling::linear;
    c.d_ref = report_number(report, path, "contact", "d_ref");
  }
  const double ks_over_kn = r.ks_over_kn.value_or(c.ks / c.kn);
  if (r.kn_ref) c.kn = *r.kn_ref;
  c.ks = ks_over_kn * c.kn;
  if (r.scaling) c.scaling = *r.scaling;
  if (r.d_ref) c.d_ref = *r.d_ref;
  // No viscous contact damping unless asked: a quasi-static test needs none (local damping
  // settles it), and against dashpots (the specimen's β = 0.5) the radial servo lagged its
  // target by 3–7 % while the specimen dilated (measured; within 0.25 % without).
  c.damping_ratio = r.damping_ratio.value_or(0.0);
  if (r.local_damping) c.local_damping = *r.local_damping;
  dem::validate(c);
  return c;
}

// The container of the specimen as a test cell: a cuboid at its recorded box, or a cylinder of
// its diameter with the platens on the specimen's bottom and top.
dem::TestCell test_cell(dem::World& world, const nlohmann::json& report, const std::string& path,
                        double z_lo, double z_hi) {
  const auto c = report.find("container");
  if (c != report.end() && c->is_object() && c->value("shape", std::string()) == "cuboid") {
    Vec3 lo, hi;
    try {
      for (int a = 0; a < 3; ++a) {
        lo[a] = c->at("lo").at(a).get<double>();
        hi[a] = c->at("hi").at(a).get<double>();
      }
    } catch (const std::exception&) {
      throw InvalidInput(path + ": field container.lo/hi missing or not three numbers");
    }
    return dem::add_cuboid_test_cell(world, lo, hi);
  }
  const double radius = 0.5 * report_number(report, path, "container", "diameter");
  if (c != report.end() && c->is_object() && c->value("shape", std::string()) == "segment")
    return dem::add_segment_test_cell(
        world, radius, report_number(report, path, "container", "angle_deg") * M_PI / 180.0, z_lo,
        z_hi);
  return dem::add_cylinder_test_cell(world, radius, z_lo, z_hi);
}

}  // namespace

TestSetup setup_test(const std::string& kind, const std::string& specimen_dir,
                     const TestRecipe& recipe, const std::string& out_dir, bool resume,
                     double checkpoint_seconds, bool allow_dynamic, double strain_rate,
                     const std::string& rate_field, const Interrupter& interrupter,
                     const std::function<void(const nlohmann::json&, const std::string&,
                                              const dem::CellSpecimen&)>& validate) {
  check_output_directory(out_dir);
  check_output_spares(out_dir, specimen_dir, "the specimen");
  const fs::path src = specimen_dir;
  const std::string report_path = (src / "report.json").string();
  const nlohmann::json spec_report = read_json_file(report_path);
  const std::vector<SpecimenBody> rows = read_specimen_csv((src / "specimen.csv").string());
  if (rows.empty()) throw InvalidInput((src / "specimen.csv").string() + ": no bodies");

  // What a checkpoint must match: the test, the recipe, the specimen and this version.
  Fnv1a fp;
  fp.add(std::string_view(kind));
  fp.add(std::string_view(recipe.text));
  fp.add(std::string_view(read_file((src / "specimen.csv").string())));
  fp.add(std::string_view(read_file(report_path)));
  // A crushable specimen's bonds between its cells' bodies (bonds.csv beside specimen.csv).
  const fs::path bonds_path = src / "bonds.csv";
  std::optional<SpecimenBonds> bonds;
  if (fs::exists(bonds_path)) {
    bonds = read_bonds_csv(bonds_path.string(), rows.size());
    fp.add(std::string_view(read_file(bonds_path.string())));
  }
  fp.add(std::string_view(CLUMPKIT_VERSION));
  const std::string fingerprint = fp.hex();

  std::vector<dem::Body> bodies;
  bodies.reserve(rows.size());
  double z_lo = 1e300, z_hi = -1e300;
  for (const SpecimenBody& b : rows) {
    bodies.push_back(dem_body(b));
    bodies.back().mass *= recipe.density_scaling;  // [test] density_scaling (1: none)
    bodies.back().moments *= recipe.density_scaling;
    for (const Sphere& s : b.spheres) {
      z_lo = std::min(z_lo, s.center.z() - s.radius);
      z_hi = std::max(z_hi, s.center.z() + s.radius);
    }
  }
  dem::WorldOptions o =
      dem::element_test_world_options(bodies, contact_law(spec_report, report_path, recipe));
  if (bonds) {
    // Bodies keep their indices: the breakage measures size each fragment from its cells as
    // built (ElementTestSettings::reference).
    o = dem::cell_packing_options(o, bonds->law);
    o.skin = dem::crushable_skin(bodies);  // above 0.2·r_min: the median is at least r_min
  }
  // Refused before anything is written unless the user asks for a dynamic test.
  const double inertial = dem::inertial_number(bodies, strain_rate, recipe.settings.confining);
  if (inertial > 1e-2 && !allow_dynamic)
    throw InvalidInput(recipe.path + ": " + rate_field + ": " + format_number(strain_rate) +
                       " gives an inertial number " + format_number(inertial, 3) +
                       " > 1e-2 on this specimen (a dynamic test, not quasi-static): lower it, or "
                       "pass --allow-dynamic");
  // The inertial number the platen is held at as the stress rises: the same bound.
  if (recipe.settings.inertial_number > 1e-2 && !allow_dynamic)
    throw InvalidInput(recipe.path +
                       ": test.inertial_number: " + format_number(recipe.settings.inertial_number) +
                       " > 1e-2 is a dynamic test, not quasi-static: lower it, or pass "
                       "--allow-dynamic");

  dem::CellSpecimen specimen{dem::World(o), {}};
  for (dem::Body& b : bodies) specimen.world.add_body(std::move(b));
  if (bonds)
    for (dem::Bond& b : bonds->bonds) specimen.world.add_bond(std::move(b));
  specimen.cell = test_cell(specimen.world, spec_report, report_path, z_lo, z_hi);
  specimen.world.options().timestep =
      recipe.timestep_safety * dem::critical_timestep(specimen.world);
  if (validate) validate(spec_report, report_path, specimen);

  // The work directory DIR.partial: with --resume, its checkpoint of the same inputs continues.
  const fs::path out = out_dir + ".partial";
  TestSetup setup;
  if (!resume)
    begin_staging(out_dir);  // afresh: an empty DIR.partial
  else
    remove_stray_temporaries(out.string());  // a killed run's half-written files
  fs::create_directories(out);
  setup.stages = std::make_unique<StageFiles>((out / "checkpoints").string(), resume);
  setup.control.store = setup.stages.get();
  setup.control.checkpoint_every_seconds = checkpoint_seconds;
  setup.control.interrupter = interrupter;

  setup.spec_report = spec_report;
  setup.report_path = report_path;
  setup.bodies = rows.size();
  setup.options = o;
  setup.inertial = inertial;
  setup.fingerprint = fingerprint;
  setup.out = out;
  setup.specimen = std::move(specimen);
  return setup;
}

LabJobResult finish_test_job(const TestSetup& setup, const std::string& out_dir,
                             const TestRecipe& recipe, const std::string& test,
                             const std::string& specimen_dir, const nlohmann::ordered_json& report,
                             const std::vector<std::string>& files, bool resume, bool resumed) {
  const fs::path& out = setup.out;
  nlohmann::ordered_json full = report;
  full["density_scaling"] = recipe.density_scaling;
  add_units(full, si_length());
  write_file_atomically((out / "report.json").string(),
                        [&](std::ostream& f) { f << full.dump(2) << "\n"; });
  nlohmann::ordered_json m = manifest_head("test", recipe.path, recipe.text, 0);
  m["test"] = test;
  m["specimen"] = specimen_dir;
  m["files"] = files;
  add_units(m, si_length());
  write_file_atomically((out / "manifest.json").string(),
                        [&](std::ostream& f) { f << m.dump(2) << "\n"; });
  publish_directory(out.string(), out_dir);
  LabJobResult result;
  result.report = std::move(full);
  result.resumed = resumed;
  if (resume && !resumed)
    result.afresh_reason = "no checkpoint in " + (out / "checkpoints").string();
  return result;
}

double radial_core_radius(const nlohmann::json& report, const std::string& report_path) {
  const auto z = report.find("zones");
  if (z == report.end() || !z->is_object() || z->value("coordinate", "") != "radial") return 0.0;
  const auto regions = z->find("regions");
  if (regions == z->end() || !regions->is_array() || regions->empty() ||
      !(*regions)[0].contains("outer") || !(*regions)[0]["outer"].is_number())
    throw InvalidInput(report_path + ": field zones.regions[0].outer missing");
  return (*regions)[0]["outer"].get<double>();
}

}  // namespace clumpkit
