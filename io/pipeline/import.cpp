#include "io/pipeline/import.h"

#include "dem/specimen/specimen.h"
#include "geom/errors.h"
#include "io/base/atomic_file.h"
#include "io/base/json_file.h"
#include "io/base/text.h"
#include "io/base/units.h"
#include "io/export/engine_settings.h"
#include "io/export/lammps_import.h"
#include "io/formats/cpt_curve.h"
#include "io/formats/specimen_csv.h"
#include "io/formats/specimen_vtp.h"
#include "io/pipeline/manifest.h"
#include "io/pipeline/output_dir.h"
#include "io/reports/cpt_report.h"
#include "io/reports/plot.h"
#include "io/reports/specimen_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace clumpkit {

namespace fs = std::filesystem;

namespace {

double field(const nlohmann::json& j, const std::string& path, const char* a,
             const char* b = nullptr) {
  const nlohmann::json* v = j.contains(a) ? &j[a] : nullptr;
  if (v && b) v = v->contains(b) ? &(*v)[b] : nullptr;
  if (!v || !v->is_number())
    throw InvalidInput(path + ": field " + std::string(a) + (b ? std::string(".") + b : "") +
                       " missing (a report of an older clumpkit; build the specimen again)");
  return v->get<double>();
}

/// The deck's oedometer.csv (strain,stress; stress_pa before units) as a curve; throws
/// InvalidInput naming the line.
PlotCurve read_oedometer(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  PlotCurve c;
  long line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#' || line.rfind("strain", 0) == 0) continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream s(line);
    double strain, stress;
    if (!(s >> strain >> stress))
      throw InvalidInput(path.string() + ":" + std::to_string(line_no) +
                         ": not a 'strain,stress' row");
    c.x.push_back(strain);
    c.y.push_back(stress / 1000);
  }
  return c;
}

// The deck's oedometer.csv copied with its header in today's form, "strain[1],stress[Pa]" (a deck
// exported before units printed "strain,stress_pa").
void copy_oedometer(const fs::path& from, const fs::path& to) {
  const std::string text = read_file(from.string());
  write_file_atomically(to.string(), [&](std::ostream& o) {
    std::istringstream in(text);
    std::string line;
    bool header = true;
    while (std::getline(in, line)) {
      std::string bare = line;
      if (!bare.empty() && bare.back() == '\r') bare.pop_back();
      if (header && !bare.empty() && bare[0] != '#') {
        header = false;
        if (column_names(split_csv(bare)) == std::vector<std::string>{"strain", "stress"}) {
          o << csv_header("oedometer", "strain,stress", si_length()) << "\n";
          continue;
        }
      }
      o << line << "\n";
    }
  });
}

// The run's bodies at its final dump, fitted to the source specimen's bodies.
struct ImportedBodies {
  std::vector<SpecimenBody> bodies;  ///< ids from 1
  std::vector<long> source_id;       ///< each body's id in the source specimen.csv
  std::string dump;
  std::size_t lost = 0;
  double fit_residual = 0;
};

ImportedBodies import_bodies(const std::string& run_dir,
                             const std::vector<SpecimenBody>& specimen) {
  ImportedBodies im;
  im.dump = final_lammps_dump(run_dir);
  const std::vector<LammpsAtom> atoms = read_lammps_dump(im.dump);
  im.bodies = bodies_from_lammps_atoms(specimen, atoms, im.dump, im.lost, im.fit_residual);
  if (im.bodies.empty()) throw InvalidInput(im.dump + ": the engine lost every body");
  for (std::size_t k = 0; k < im.bodies.size(); ++k) {
    im.source_id.push_back(im.bodies[k].id);
    im.bodies[k].id = static_cast<long>(k + 1);
  }
  return im;
}

// specimen.csv, specimen.vtp and bodies_map.csv of the imported bodies.
std::vector<std::string> write_imported_bodies(const fs::path& staging, const ImportedBodies& im) {
  write_specimen_csv((staging / "specimen.csv").string(), im.bodies);
  write_specimen_vtp((staging / "specimen.vtp").string(), im.bodies);
  write_file_atomically((staging / "bodies_map.csv").string(), [&](std::ostream& o) {
    o << "# imported body id -> body id of the source specimen.csv\n"
      << csv_header("bodies_map", "body,source_body", si_length()) << "\n";
    for (std::size_t k = 0; k < im.bodies.size(); ++k) o << k + 1 << "," << im.source_id[k] << "\n";
  });
  return {"specimen.csv", "specimen.vtp", "bodies_map.csv"};
}

// report.json's head: where the run came from and how well its bodies fitted.
nlohmann::ordered_json import_head(const std::string& engine, const std::string& run_dir,
                                   const fs::path& src, const ImportedBodies& im) {
  nlohmann::ordered_json r;
  r["engine"] = engine;
  r["run_dir"] = fs::absolute(run_dir).lexically_normal().string();
  r["dump"] = fs::absolute(im.dump).lexically_normal().string();
  r["source"] = fs::absolute(src).lexically_normal().string();
  r["bodies"] = im.bodies.size();
  r["lost_bodies"] = im.lost;
  r["fit_residual"] = im.fit_residual;
  return r;
}

// report.json and manifest.json into `staging`.
void finish_import(const fs::path& staging, const std::string& engine, nlohmann::ordered_json& r,
                   std::vector<std::string>& names) {
  add_units(r, si_length());
  write_file_atomically((staging / "report.json").string(),
                        [&](std::ostream& o) { o << r.dump(2) << "\n"; });
  nlohmann::ordered_json m = manifest_head("import", "", "", 0);
  m["engine"] = engine;
  m["run_dir"] = r["run_dir"];
  m["source"] = r["source"];
  add_units(m, si_length());
  write_file_atomically((staging / "manifest.json").string(),
                        [&](std::ostream& o) { o << m.dump(2) << "\n"; });
  names.push_back("report.json");
  names.push_back("manifest.json");
}

// A run of the CPT deck: its push (cpt.csv) as `clumpkit test cpt` reports one, and the final
// state of its bodies.
ImportResult import_cpt(const std::string& engine, const std::string& run_dir, const fs::path& src,
                        const nlohmann::json& report, const std::vector<SpecimenBody>& specimen,
                        const std::string& out_dir) {
  const std::vector<dem::CptRow> curve = read_cpt_curve((fs::path(run_dir) / "cpt.csv").string());
  const ImportedBodies im = import_bodies(run_dir, specimen);
  ImportResult result;
  result.engine = engine;
  result.bodies = im.bodies.size();
  result.lost = im.lost;
  result.fit_residual = im.fit_residual;
  std::vector<std::string> names;
  write_staged(out_dir, [&](const std::string& dir) {
    const fs::path staging = dir;
    names = write_imported_bodies(staging, im);
    write_cpt_curve((staging / "curve.csv").string(), curve);
    write_cpt_plot((staging / "curve.png").string(), curve, "CPT in " + engine);
    names.push_back("curve.csv");
    names.push_back("curve.png");
    nlohmann::ordered_json r = import_head(engine, run_dir, src, im);
    r["test"] = "cpt";
    r["steps"] = curve.back().step;
    r["final_depth"] = curve.back().depth;
    add_cpt_summary(r, curve);
    for (const char* key : {"container", "density", "contact"})
      if (report.contains(key)) r[key] = report[key];
    finish_import(staging, engine, r, names);
  });
  for (const std::string& n : names) result.files.push_back((fs::path(out_dir) / n).string());
  return result;
}

}  // namespace

ImportResult run_import(const std::string& engine, const std::string& run_dir,
                        const std::string& specimen_dir, const std::string& out_dir) {
  if (engine != "lammps")
    throw InvalidInput("import: unknown engine '" + engine + "' (available: lammps)");
  check_output_spares(out_dir, specimen_dir, "the specimen");
  check_output_spares(out_dir, run_dir, "the run directory");
  const fs::path src(specimen_dir);
  if (!fs::exists(src / "specimen.csv"))
    throw InvalidInput(specimen_dir + ": not a specimen directory (no specimen.csv)");
  const std::string report_path = (src / "report.json").string();
  const nlohmann::json report = read_json_file(report_path);
  const EngineSettings settings = engine_settings_from_report(report, report_path);
  const std::vector<SpecimenBody> specimen = read_specimen_csv((src / "specimen.csv").string());
  if (fs::exists(fs::path(run_dir) / "cpt.csv"))
    return import_cpt(engine, run_dir, src, report, specimen, out_dir);
  const ImportedBodies im = import_bodies(run_dir, specimen);
  const std::vector<SpecimenBody>& bodies = im.bodies;
  ImportResult result;
  result.engine = engine;
  result.lost = im.lost;
  result.fit_residual = im.fit_residual;

  // Measure as the specimen command does: same container, margin and layers.
  dem::SpecimenResult measured;
  for (const SpecimenBody& b : bodies) measured.world.add_body(dem_body(b));
  // One step of negligible length finds the contacts (for the coordination number).
  measured.world.options().gravity = Vec3::Zero();
  measured.world.options().timestep = 1e-30;
  measured.world.step();
  measured.porosity_max = field(report, report_path, "porosity_max");
  measured.porosity_min = field(report, report_path, "porosity_min");
  const double margin =
      settings.container_radius - field(report, report_path, "measurement_region", "radius");
  if (!report.contains("layer_porosity") || !report["layer_porosity"].is_array())
    throw InvalidInput(report_path + ": field layer_porosity missing");
  const int layers = static_cast<int>(report["layer_porosity"].size());
  dem::measure_specimen(measured.world, settings.container_radius, margin, layers, measured);
  result.bodies = bodies.size();
  result.porosity = measured.porosity;
  result.relative_density = measured.relative_density;
  result.source_relative_density = field(report, report_path, "relative_density");
  result.height = measured.height;
  const bool oedometer = fs::exists(fs::path(run_dir) / "oedometer.csv");
  const PlotCurve curve =
      oedometer ? read_oedometer(fs::path(run_dir) / "oedometer.csv") : PlotCurve{};

  std::vector<std::string> names;
  write_staged(out_dir, [&](const std::string& dir) {
    const fs::path staging = dir;
    names = write_imported_bodies(staging, im);
    std::vector<double> heights;
    const int slices = 2 * layers + 1;
    for (int k = 1; k <= slices; ++k) heights.push_back(measured.height * k / (slices + 1));
    for (const std::string& f :
         write_slices((staging / "slices").string(), measured, settings.container_radius, heights))
      names.push_back("slices/" + f);
    if (oedometer) {
      copy_oedometer(fs::path(run_dir) / "oedometer.csv", staging / "oedometer.csv");
      write_line_plot((staging / "oedometer.png").string(), curve, "vertical strain (-)",
                      "vertical stress (kPa)",
                      "oedometer test in " + engine + " (compression positive)");
      names.push_back("oedometer.csv");
      names.push_back("oedometer.png");
    }
    nlohmann::ordered_json r = import_head(engine, run_dir, src, im);
    r["porosity"] = measured.porosity;
    r["relative_density"] = measured.relative_density;
    r["source_relative_density"] = result.source_relative_density;
    r["source_porosity"] = field(report, report_path, "porosity");
    r["porosity_max"] = measured.porosity_max;
    r["porosity_min"] = measured.porosity_min;
    r["height"] = measured.height;
    r["layer_porosity"] = measured.layer_porosity;
    r["band_porosity"] = measured.band_porosity;
    r["coordination_number"] = measured.coordination;
    r["measurement_region"] = {{"radius", measured.region.radius},
                               {"z_lo", measured.region.z_lo},
                               {"z_hi", measured.region.z_hi}};
    r["container"] = report["container"];
    r["density"] = report["density"];
    r["contact"] = report["contact"];
    finish_import(staging, engine, r, names);
  });
  for (const std::string& n : names) result.files.push_back((fs::path(out_dir) / n).string());
  return result;
}

}  // namespace clumpkit
