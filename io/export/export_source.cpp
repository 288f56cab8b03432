#include "io/export/export_source.h"

#include "dem/specimen/deposition.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "geom/mesh/mesh.h"
#include "geom/template/clump_template.h"
#include "io/base/json_file.h"
#include "io/formats/clump_io.h"
#include "io/formats/library_table.h"
#include "io/formats/mesh_io.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace clumpkit {

namespace fs = std::filesystem;

namespace {

// The mesh a clump CSV was filled from: STEM.stl (or .obj, .ply) beside it, STEM being the file
// name up to its first '.' (a library's NNNNN.csv and NNNNN.template.csv both name NNNNN.stl).
fs::path mesh_beside(const fs::path& clump_csv) {
  const std::string name = clump_csv.filename().string();
  const std::string stem = name.substr(0, name.find('.'));
  for (const char* ext : {".stl", ".obj", ".ply"}) {
    const fs::path p = clump_csv.parent_path() / (stem + ext);
    if (fs::is_regular_file(p)) return p;
  }
  throw InvalidInput(clump_csv.string() + ": --mass mesh needs the particle's mesh, and no " +
                     stem + ".stl (.obj, .ply) lies beside it");
}

// A template in SI (lengths × u, V × u³, I × u⁵) at unit density, its mass and moments times
// the mass-equivalence factor (1, or V_mesh/V_clump); the density comes in layout_templates.
TemplateBody scaled_template(const ClumpTemplate& c, double u, double factor, int template_id) {
  TemplateBody t;
  t.template_id = template_id;
  for (const Sphere& s : c.spheres) t.spheres.push_back({u * s.center, u * s.radius});
  t.volume = std::pow(u, 3) * c.mass.volume;
  t.mass = factor * t.volume;
  t.moments = factor * std::pow(u, 5) * c.principal_moments;
  return t;
}

std::vector<TemplateBody> library_templates(const fs::path& dir, double u, bool mesh_mass) {
  const std::vector<dem::RockTemplate> rock = read_rock_templates(dir.string());
  const std::vector<double> factor = mesh_mass ? read_library_column(dir.string(), "density_factor")
                                               : std::vector<double>(rock.size(), 1.0);
  std::vector<TemplateBody> out;
  for (std::size_t i = 0; i < rock.size(); ++i)
    out.push_back(scaled_template(rock[i].clump, u, factor[i], static_cast<int>(i)));
  return out;
}

TemplateBody clump_template(const fs::path& csv, double u, bool mesh_mass) {
  const Clump clump = read_clump(csv.string());
  double mesh_volume = 0;
  if (mesh_mass) mesh_volume = std::abs(signed_volume(read_mesh(mesh_beside(csv).string())));
  const ClumpTemplate c = make_clump_template(clump, mesh_volume);
  if (!(c.mass.volume > 0) || !std::isfinite(c.mass.volume) || !c.principal_moments.allFinite() ||
      !(c.principal_moments.minCoeff() > 0))
    throw InvalidInput(csv.string() +
                       ": the clump's volume and moments are not positive and "
                       "finite (volume " +
                       format_number(c.mass.volume) + ")");
  return scaled_template(c, u, mesh_mass ? c.density_factor : 1.0, 0);
}

}  // namespace

std::vector<SpecimenBody> layout_templates(const std::vector<TemplateBody>& templates,
                                           double density, EngineSettings& settings) {
  double reach_max = 0;
  std::vector<double> reach;
  for (const TemplateBody& t : templates) {
    double r = 0;
    for (const Sphere& s : t.spheres) r = std::max(r, s.center.norm() + s.radius);
    reach.push_back(r);
    reach_max = std::max(reach_max, r);
  }
  const int side = static_cast<int>(std::ceil(std::sqrt(double(templates.size()))));
  const double spacing = 2.4 * reach_max;
  std::vector<SpecimenBody> bodies;
  for (std::size_t k = 0; k < templates.size(); ++k) {
    const TemplateBody& t = templates[k];
    SpecimenBody b;
    b.id = static_cast<long>(k) + 1;
    b.kind = dem::BodyKind::rock;
    b.template_id = t.template_id;
    const int i = static_cast<int>(k) % side, j = static_cast<int>(k) / side;
    b.position = Vec3((i - 0.5 * (side - 1)) * spacing, (j - 0.5 * (side - 1)) * spacing,
                      reach[k] + 0.1 * reach_max);
    b.mass = density * t.mass;
    b.volume = t.volume;
    b.moments = density * t.moments;
    for (const Sphere& s : t.spheres) b.spheres.push_back({s.center + b.position, s.radius});
    bodies.push_back(std::move(b));
  }
  // The grid's corners lie (side − 1)/2 · spacing · √2 from the axis.
  settings.container_radius =
      0.5 * (side - 1) * spacing * std::sqrt(2.0) + reach_max + 0.5 * spacing;
  settings.container_height = 2 * spacing;
  settings.rock_density = settings.soil_density = density;
  settings.contact = dem::deposition_contact();
  return bodies;
}

ExportSource read_export_source(const std::string& source, const TemplateSourceOptions& options) {
  const fs::path src(source);
  if (!fs::exists(src)) throw IoError(source + ": no such file or directory");
  ExportSource out;
  const bool specimen = fs::is_directory(src) && fs::exists(src / "specimen.csv");
  if (specimen) {
    if (!std::isnan(options.density) || !options.length_unit.empty() || !options.mass.empty())
      throw InvalidInput(source +
                         ": a specimen carries its own densities, masses and units (SI); "
                         "--density, --length-unit and --mass are for a library or clump CSV");
    out.kind = "specimen";
    const nlohmann::json report = read_json_file((src / "report.json").string());
    out.manifest = read_json_file((src / "manifest.json").string());
    out.settings = engine_settings_from_report(report, (src / "report.json").string());
    out.report = report;
    out.bodies = read_specimen_csv((src / "specimen.csv").string());
    return out;
  }
  const bool library = fs::is_directory(src) && fs::exists(src / "library.csv");
  if (fs::is_directory(src) && !library)
    throw InvalidInput(source +
                       ": neither a specimen nor a library directory (no specimen.csv or "
                       "library.csv)");
  if (!library && !fs::is_regular_file(src))
    throw InvalidInput(source + ": not a specimen or library directory, nor a clump CSV");

  const std::string what = library ? "a clump library" : "a clump CSV";
  if (std::isnan(options.density))
    throw InvalidInput(source + ": " + what + " needs --density (kg/m3) for its masses");
  if (!(options.density > 0) || !std::isfinite(options.density))
    throw InvalidInput("--density must be a positive density in kg/m3, got " +
                       format_number(options.density));
  double u = 1.0;
  if (options.length_unit == "mm")
    u = 1e-3;
  else if (!options.length_unit.empty() && options.length_unit != "m")
    throw InvalidInput("--length-unit must be m or mm, got '" + options.length_unit + "'");
  if (!options.mass.empty() && options.mass != "clump" && options.mass != "mesh")
    throw InvalidInput("--mass must be clump or mesh, got '" + options.mass + "'");
  const bool mesh_mass = options.mass == "mesh";

  std::vector<TemplateBody> templates;
  if (library) {
    out.kind = "library";
    templates = library_templates(src, u, mesh_mass);
    if (fs::exists(src / "manifest.json"))
      out.manifest = read_json_file((src / "manifest.json").string());
  } else {
    out.kind = "clump";
    templates.push_back(clump_template(src, u, mesh_mass));
  }
  out.templates = true;
  out.bodies = layout_templates(templates, options.density, out.settings);
  return out;
}

}  // namespace clumpkit
