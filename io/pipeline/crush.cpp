#include "io/pipeline/crush.h"

#include "dem/core/bond.h"
#include "dem/core/crushable.h"
#include "dem/lab/weibull.h"
#include "geom/cells/cell_bonds.h"
#include "geom/errors.h"
#include "geom/shapes/primitives.h"
#include "io/base/atomic_file.h"
#include "io/base/json_file.h"
#include "io/base/text.h"
#include "io/base/units.h"
#include "io/formats/cells_files.h"
#include "io/pipeline/manifest.h"
#include "io/pipeline/output_dir.h"
#include "io/reports/plot.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <mutex>
#include <sstream>

namespace fs = std::filesystem;

namespace clumpkit {

namespace {

// The parent turned so that its largest face within 30° of the lower platen (normal −axis)
// lies flat on it; with no face that close, the face closest to it. A convex parent's faces are
// its distinct triangle planes (convex_planes); a face's area is that of its triangles.
Mesh rest_on_face(Mesh mesh, int axis) {
  const std::vector<Halfspace> planes = convex_planes(mesh);
  const Vec3 down = -Vec3::Unit(axis);
  std::vector<double> area(planes.size(), 0.0);
  for (const auto& t : mesh.triangles) {
    const Vec3 e = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                       .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    const double a = 0.5 * e.norm();
    if (!(a > 0)) continue;
    const Vec3 n = e.normalized();
    std::size_t best = 0;
    for (std::size_t p = 1; p < planes.size(); ++p)
      if (planes[p].normal.dot(n) > planes[best].normal.dot(n)) best = p;
    area[best] += a;
  }
  const double near = std::cos(M_PI / 6);
  std::size_t pick = planes.size();
  for (std::size_t p = 0; p < planes.size(); ++p)
    if (planes[p].normal.dot(down) >= near && (pick == planes.size() || area[p] > area[pick]))
      pick = p;
  if (pick == planes.size()) {
    pick = 0;
    for (std::size_t p = 1; p < planes.size(); ++p)
      if (planes[p].normal.dot(down) > planes[pick].normal.dot(down)) pick = p;
  }
  const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(planes[pick].normal, down);
  for (Vec3& v : mesh.vertices) v = turn * v;
  return mesh;
}

Mesh make_parent(const CrushSet& s, Rng& rng) {
  Mesh m = s.shape == "cylinder" ? make_cylinder(s.polyhedron.diameter, s.height, s.sides)
                                 : make_polyhedron(s.polyhedron, rng);
  return s.rest_on_face ? rest_on_face(std::move(m), s.axis) : m;
}

std::string file_safe(const std::string& name) {
  std::string s = name;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return s;
}

struct Job {
  std::size_t set = 0, sample = 0;
};

nlohmann::ordered_json crush_one(const CrushRecipe& recipe, const Job& job, std::size_t id,
                                 const fs::path& parts) {
  const CrushSet& s = recipe.sets[job.set];
  Rng rng = Rng::stream(recipe.seed, id);
  const Mesh parent = make_parent(s, rng);
  const Tessellation cells = voronoi_cells(parent, recipe.cells, rng);
  const std::vector<CellBond> bonds =
      cell_bonds(cells, recipe.strength, rng, recipe.face_subdivision);
  dem::WorldOptions wo;
  wo.cohesive = recipe.law;
  dem::World world = dem::crushable_particle(cells, bonds, recipe.density, wo);
  const double diameter = std::cbrt(6.0 * cells.parent_volume / M_PI);
  dem::CrushOptions rig = recipe.rig;
  rig.axis = s.axis;
  std::vector<CellPose> before, after;
  for (const dem::Body& b : world.bodies()) before.push_back({b.position, b.orientation});
  const dem::CrushResult r = dem::crush_particle(world, diameter, rig);
  for (const dem::Body& b : world.bodies()) after.push_back({b.position, b.orientation});

  const std::string stem = id_name(id);
  write_file_atomically((parts / (stem + ".csv")).string(), [&](std::ostream& o) {
    o << csv_header("crush_curve", "travel,force,split", si_length()) << "\n"
      << std::setprecision(17);
    for (const dem::CrushSample& x : r.samples)
      o << x.travel << "," << x.force << "," << (x.split ? 1 : 0) << "\n";
  });
  // The cells before and after for the page (fragments numbered from 1 in cell order).
  const std::vector<int> fragment = dem::fragment_ordinals(
      dem::fragments(static_cast<int>(world.bodies().size()), world.bonds()));
  write_cell_motion((parts / (stem + ".cells.json")).string(), cells, before, after, fragment);
  std::size_t points = 0;
  for (const CellBond& b : bonds) points += b.points.size();
  nlohmann::ordered_json rec;
  rec["id"] = id;
  rec["set"] = s.name;
  rec["sample"] = job.sample;
  rec["diameter"] = diameter;
  rec["cells"] = cells.cells.size();
  rec["bedded"] = r.bedded;
  rec["bonds"] = bonds.size();
  rec["bond_points"] = points;
  rec["gap"] = r.gap;
  rec["timestep"] = r.timestep;
  rec["steps"] = r.steps;
  rec["failed"] = r.peak.found;
  rec["peak_force"] = r.peak.force;
  rec["peak_travel"] = r.peak.travel;
  rec["failure"] = r.peak.by;
  rec["strength"] = r.peak.found ? r.peak.force / (diameter * diameter) : 0.0;
  rec["fragments"] = r.fragments;
  rec["largest_fragment"] = r.largest_fragment;
  rec["imbalance"] = r.imbalance;
  rec["curve_file"] = "particles/" + stem + ".csv";
  add_units(rec, si_length());
  write_sealed_record((parts / (stem + ".json")).string(), rec);
  return rec;
}

nlohmann::json pair(double a, double b) {
  return nlohmann::json::array({a, b});
}

std::vector<dem::CrushSample> read_curve(const fs::path& path) {
  std::vector<dem::CrushSample> out;
  std::istringstream in(read_file(path.string()));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    dem::CrushSample s;
    char comma = 0;
    int split = 0;
    std::istringstream row(line);
    row >> s.travel >> comma >> s.force >> comma >> split;
    out.push_back(s);
  }
  return out;
}

// The colours of a plot's series, in turn.
const std::array<std::array<unsigned char, 3>, 6> kCrushColours{
    {{20, 70, 180}, {200, 60, 40}, {30, 150, 60}, {150, 60, 170}, {230, 140, 20}, {60, 60, 60}}};

// The partial directory: started afresh unless it was started from this very recipe, cleared of
// stray temporaries and stamped with the recipe.
void prepare_crush_partial(const CrushRecipe& recipe, const fs::path& out, const fs::path& parts) {
  const fs::path stamp = out / "recipe.toml";
  std::error_code ec;
  if (fs::exists(out) && !(fs::exists(stamp) && read_file(stamp.string()) == recipe.text))
    fs::remove_all(out, ec);
  remove_stray_temporaries(out.string());
  fs::create_directories(parts, ec);
  if (ec) throw IoError(out.string() + ": cannot create directory: " + ec.message());
  write_file_atomically(stamp.string(), [&](std::ostream& o) { o << recipe.text; });
}

// The particles still to crush: those without a record and a curve of an earlier run, or whose
// record is damaged (noted as redone). The others' records are read back and counted resumed.
std::vector<std::size_t> resume_crush_particles(const fs::path& parts,
                                                std::vector<nlohmann::ordered_json>& records,
                                                CrushJobResult& result) {
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const fs::path rec = parts / (id_name(i) + ".json");
    if (fs::exists(rec) && fs::exists(parts / (id_name(i) + ".csv"))) {
      if (read_sealed_record(rec.string(), records[i])) {
        ++result.resumed;
        continue;
      }
      result.redone.push_back("particles/" + id_name(i) + ".json");
    }
    todo.push_back(i);
  }
  return todo;
}

// Crushes the particles to do into their records; true when the interrupter stopped the run.
// The first particle's failure is rethrown (an invalid input with the recipe's path).
bool crush_particles(const CrushRecipe& recipe, const std::vector<Job>& jobs,
                     const std::vector<std::size_t>& todo, const fs::path& parts,
                     std::vector<nlohmann::ordered_json>& records, std::size_t resumed,
                     const Interrupter& interrupter) {
  const std::size_t total = jobs.size();
  // Particles in parallel, each deterministic on its own stream; the interrupter is asked
  // between particles, from one thread at a time.
  std::mutex tell;
  std::atomic<bool> stop{false};
  std::atomic<std::size_t> done{resumed};
  std::exception_ptr failure;
  tbb::parallel_for(std::size_t(0), todo.size(), [&](std::size_t k) {
    if (stop.load()) return;
    const std::size_t i = todo[k];
    try {
      records[i] = crush_one(recipe, jobs[i], i, parts);
    } catch (...) {
      std::lock_guard<std::mutex> lock(tell);
      if (!failure) failure = std::current_exception();
      stop = true;
      return;
    }
    std::lock_guard<std::mutex> lock(tell);
    if (interrupted(interrupter, "crush", Progress(++done, total))) stop = true;
  });
  if (failure) {
    try {
      std::rethrow_exception(failure);
    } catch (const InvalidInput& e) {
      throw InvalidInput(recipe.path + ": " + e.what());
    }
  }
  return stop.load();
}

// Per particle table (results.csv), with the largest force of each curve.
void write_crush_results(const fs::path& out, const std::vector<nlohmann::ordered_json>& records,
                         const std::vector<double>& max_force) {
  const std::size_t total = records.size();
  write_file_atomically((out / "results.csv").string(), [&](std::ostream& o) {
    o << csv_header("results",
                    "id,set,sample,diameter,cells,bonds,failed,failure,peak_force,peak_travel,"
                    "strength,fragments,largest_fragment,imbalance,steps,max_force",
                    si_length())
      << "\n"
      << std::setprecision(17);
    for (std::size_t i = 0; i < total; ++i) {
      const auto& r = records[i];
      o << r["id"].get<std::size_t>() << "," << r["set"].get<std::string>() << ","
        << r["sample"].get<std::size_t>() << "," << r["diameter"].get<double>() << ","
        << r["cells"].get<std::size_t>() << "," << r["bonds"].get<std::size_t>() << ","
        << (r["failed"].get<bool>() ? 1 : 0) << "," << r["failure"].get<std::string>() << ","
        << r["peak_force"].get<double>() << "," << r["peak_travel"].get<double>() << ","
        << r["strength"].get<double>() << "," << r["fragments"].get<int>() << ","
        << r["largest_fragment"].get<double>() << "," << r["imbalance"].get<double>() << ","
        << r["steps"].get<long long>() << "," << max_force[i] << "\n";
    }
  });
}

// The Weibull statistics of a run: each set's strengths and survivors, its fits, and the size law
// across the sets that ask for it; the state its steps share.
struct CrushStatistics {
  CrushStatistics(const CrushRecipe& crush_recipe, std::size_t particles)
      : recipe(crush_recipe),
        total(particles),
        strengths(crush_recipe.sets.size()),
        survived(crush_recipe.sets.size()),
        set_diameter(crush_recipe.sets.size(), 0.0),
        set_force(crush_recipe.sets.size(), 0.0) {}

  // Each particle into its set: a failed one by its strength and peak force, another (when it
  // carried a load) by the largest stress it carried.
  void tally(const std::vector<Job>& jobs, const std::vector<nlohmann::ordered_json>& records,
             const std::vector<double>& max_force) {
    for (std::size_t i = 0; i < total; ++i) {
      const auto& r = records[i];
      const std::size_t s = jobs[i].set;
      const double d = r["diameter"].get<double>();
      set_diameter[s] += d / recipe.sets[s].samples;
      if (r["failed"].get<bool>()) {
        strengths[s].push_back(r["strength"].get<double>());
        set_force[s] += r["peak_force"].get<double>();
      } else if (max_force[i] > 0.0) {
        survived[s].push_back(max_force[i] / (d * d));
      }
    }
  }

  // Set s's entry of the report; a fit also adds the set to the size law (when it asks) and
  // its points to the Weibull plot.
  nlohmann::ordered_json fit_set(std::size_t s) {
    const CrushSet& cs = recipe.sets[s];
    nlohmann::ordered_json j;
    j["name"] = cs.name;
    j["diameter"] = set_diameter[s];
    j["axis"] = std::string(cs.axis == 0 ? "long" : cs.axis == 1 ? "intermediate" : "short");
    j["samples"] = cs.samples;
    j["failed"] = strengths[s].size();
    j["survived"] = survived[s].size();
    std::vector<double> v = strengths[s];
    const std::vector<double>& c = survived[s];
    double mean = 0;
    for (double x : v) mean += x / double(std::max<std::size_t>(1, v.size()));
    j["mean_strength"] = mean;
    j["mean_peak_force"] = v.empty() ? 0.0 : set_force[s] / double(v.size());
    const bool spread = v.size() >= 3 && *std::max_element(v.begin(), v.end()) >
                                             *std::min_element(v.begin(), v.end());
    if (spread) {
      Rng boot = Rng::stream(recipe.seed, total + 2 * s);
      const dem::WeibullEstimate ls =
          dem::weibull_bootstrap(v, c, dem::WeibullMethod::least_squares, recipe.bootstrap, boot);
      Rng boot_ml = Rng::stream(recipe.seed, total + 2 * s + 1);
      const dem::WeibullEstimate ml = dem::weibull_bootstrap(
          v, c, dem::WeibullMethod::maximum_likelihood, recipe.bootstrap, boot_ml);
      j["sigma0"] = ls.fit.sigma0;
      j["sigma0_ci90"] = pair(ls.sigma0_lo, ls.sigma0_hi);
      j["weibull_modulus"] = ls.fit.modulus;
      j["weibull_modulus_ci90"] = pair(ls.modulus_lo, ls.modulus_hi);
      j["sigma0_ml"] = ml.fit.sigma0;
      j["sigma0_ml_ci90"] = pair(ml.sigma0_lo, ml.sigma0_hi);
      j["weibull_modulus_ml"] = ml.fit.modulus;
      j["weibull_modulus_ml_ci90"] = pair(ml.modulus_lo, ml.modulus_hi);
      if (cs.size_law) {
        law_d.push_back(set_diameter[s]);
        law_sigma.push_back(ls.fit.sigma0);
        law_sets.push_back(s);
      }
      PlotSeries p;
      for (const auto& [sigma, ps] : dem::weibull_plotting_positions(v, c)) {
        p.points.x.push_back(std::log(sigma * 1e-6));
        p.points.y.push_back(std::log(std::log(1.0 / ps)));
      }
      p.label = cs.name;
      p.rgb = kCrushColours[s % kCrushColours.size()];
      p.line = false;
      p.marker = 4;
      weibull_plot.push_back(p);
    } else {
      j["sigma0"] = nullptr;
      j["weibull_modulus"] = nullptr;
      j["note"] = "fewer than 3 failed samples with distinct strengths: no fit";
    }
    return j;
  }

  // The size law across the fitted sets of distinct diameters, into the report and size.png.
  void fit_size_law(nlohmann::ordered_json& report, const fs::path& out) {
    bool distinct = false;
    for (double d : law_d) distinct = distinct || d != law_d.front();
    if (law_d.size() >= 2 && distinct) {
      const dem::SizeLaw law = dem::size_law(law_d, law_sigma);
      report["size_exponent"] = law.exponent;
      report["size_coefficient"] = law.coefficient;
      report["spearman"] = dem::spearman(law_d, law_sigma);
      // Bootstrap of α: each set's strengths resampled, σ0 refitted, the law fitted again.
      Rng boot = Rng::stream(recipe.seed, total + 2 * recipe.sets.size());
      std::vector<double> alphas;
      for (int b = 0; b < recipe.bootstrap; ++b) {
        std::vector<double> s0;
        for (std::size_t s : law_sets) {
          const auto [f, c] = dem::weibull_resample(strengths[s], survived[s], boot);
          s0.push_back(dem::weibull_least_squares(f, c).sigma0);
        }
        alphas.push_back(dem::size_law(law_d, s0).exponent);
      }
      std::sort(alphas.begin(), alphas.end());
      const auto at = [&](double q) {
        return alphas[std::min(alphas.size() - 1, std::size_t(q * double(alphas.size())))];
      };
      report["size_exponent_ci90"] = pair(at(0.05), at(0.95));
      PlotSeries pts, fit;
      for (std::size_t k = 0; k < law_d.size(); ++k) {
        pts.points.x.push_back(law_d[k] * 1e3);
        pts.points.y.push_back(law_sigma[k] * 1e-6);
      }
      pts.line = false;
      pts.marker = 5;
      pts.label = "sigma0 of each set";
      const double lo = *std::min_element(law_d.begin(), law_d.end());
      const double hi = *std::max_element(law_d.begin(), law_d.end());
      for (int k = 0; k <= 50; ++k) {
        const double d = lo + (hi - lo) * k / 50.0;
        fit.points.x.push_back(d * 1e3);
        fit.points.y.push_back(law.coefficient * std::pow(d, -law.exponent) * 1e-6);
      }
      fit.label = "sigma0 = k D^-alpha";
      fit.rgb = {200, 60, 40};
      write_plot((out / "size.png").string(), {pts, fit}, "D (mm)", "sigma0 (MPa)",
                 "Characteristic strength against size");
    } else {
      report["size_exponent"] = nullptr;
      report["size_coefficient"] = nullptr;
    }
  }

  const CrushRecipe& recipe;
  const std::size_t total;
  std::vector<std::vector<double>> strengths, survived;
  std::vector<double> set_diameter, set_force;
  std::vector<double> law_d, law_sigma;
  std::vector<std::size_t> law_sets;
  std::vector<PlotSeries> weibull_plot;
};

// The crushing curves of each set, one plot per set.
void plot_crush_curves(const CrushRecipe& recipe, const std::vector<Job>& jobs,
                       const std::vector<std::vector<dem::CrushSample>>& curve,
                       const fs::path& out) {
  const std::size_t total = jobs.size();
  for (std::size_t s = 0; s < recipe.sets.size(); ++s) {
    std::vector<PlotSeries> curves;
    for (std::size_t i = 0; i < total; ++i) {
      if (jobs[i].set != s) continue;
      PlotSeries c;
      for (const dem::CrushSample& x : curve[i]) {
        c.points.x.push_back(x.travel * 1e3);
        c.points.y.push_back(x.force * 1e-3);
      }
      c.rgb = kCrushColours[curves.size() % kCrushColours.size()];
      curves.push_back(c);
    }
    write_plot((out / ("curves_" + file_safe(recipe.sets[s].name) + ".png")).string(), curves,
               "platen travel (mm)", "force (kN)", "Crushing curves: " + recipe.sets[s].name);
  }
}

}  // namespace

CrushJobResult run_crush(const CrushRecipe& recipe, const std::string& out_dir,
                         const Interrupter& interrupter) {
  check_output_directory(out_dir);
  std::vector<Job> jobs;
  for (std::size_t s = 0; s < recipe.sets.size(); ++s)
    for (int k = 0; k < recipe.sets[s].samples; ++k) jobs.push_back({s, std::size_t(k)});
  const std::size_t total = jobs.size();

  const fs::path out = out_dir + ".partial", parts = out / "particles";
  prepare_crush_partial(recipe, out, parts);

  CrushJobResult result;
  result.particles = total;
  std::vector<nlohmann::ordered_json> records(total);
  const std::vector<std::size_t> todo = resume_crush_particles(parts, records, result);

  if (crush_particles(recipe, jobs, todo, parts, records, result.resumed, interrupter))
    throw Interrupted("crush interrupted; the finished particles are kept in " + out.string() +
                      " for a rerun");

  // Every curve, read once: the largest force of each (a survivor's strength lies above it over
  // D²) and the plots of each set.
  std::vector<std::vector<dem::CrushSample>> curve(total);
  std::vector<double> max_force(total, 0.0);
  for (std::size_t i = 0; i < total; ++i) {
    curve[i] = read_curve(parts / (id_name(i) + ".csv"));
    for (const dem::CrushSample& x : curve[i]) max_force[i] = std::max(max_force[i], x.force);
  }

  write_crush_results(out, records, max_force);

  // Weibull statistics per set (Hu et al. 2023 eq. 12), bootstrap streams after the particles'.
  // A particle that did not fail within the test (tipped over, or pressed flat without a load
  // drop) enters as a right-censored sample at the largest stress it carried.
  nlohmann::ordered_json report;
  report["recipe"] = recipe.path;
  report["particles"] = total;
  report["units_note"] = "SI (the paper's mm and MPa: × 1e3 and × 1e-6)";
  report["bond_scale"] = recipe.scale;
  report["density_scaling"] = recipe.rig.density_scaling;
  report["bed_depth"] = recipe.rig.bed_depth;
  report["survivors"] =
      "a particle without a failure by the end of its test enters its set's fits as a "
      "right-censored sample at the largest stress it carried (least squares: Johnson's adjusted "
      "ranks; maximum likelihood: its survival probability)";
  CrushStatistics stats(recipe, total);
  stats.tally(jobs, records, max_force);
  auto& sets = report["sets"];
  for (std::size_t s = 0; s < recipe.sets.size(); ++s) sets.push_back(stats.fit_set(s));
  stats.fit_size_law(report, out);
  if (!stats.weibull_plot.empty())
    write_plot((out / "weibull.png").string(), stats.weibull_plot, "ln sigma (sigma in MPa)",
               "ln ln(1/Ps)", "Weibull plot");
  plot_crush_curves(recipe, jobs, curve, out);
  add_units(report, si_length());
  write_file_atomically((out / "report.json").string(),
                        [&](std::ostream& o) { o << report.dump(2) << "\n"; });
  nlohmann::ordered_json m = manifest_head("crush", recipe.path, recipe.text, recipe.seed);
  m["particles"] = total;
  m["sets"] = recipe.sets.size();
  m["files"] = {"particles/", "results.csv",    "report.json", "weibull.png",
                "size.png",   "curves_SET.png", "recipe.toml"};
  add_units(m, si_length());
  write_file_atomically((out / "manifest.json").string(),
                        [&](std::ostream& o) { o << m.dump(2) << "\n"; });
  publish_directory(out.string(), out_dir);
  result.report = report;
  return result;
}

}  // namespace clumpkit
