#include "io/specimen_io.h"

#include "dem/deposition.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "io/atomic_file.h"
#include "io/clump_io.h"
#include "io/plot.h"
#include "io/png.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace clumpkit {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  return out;
}

// Opens a library.csv and returns its header cells; `in` is left at the first row.
std::vector<std::string> open_library_csv(const fs::path& csv, std::ifstream& in) {
  in.open(csv);
  if (!in) throw IoError(csv.string() + ": cannot open clump library table");
  std::string line;
  std::getline(in, line);
  return split(line);
}

}  // namespace

std::vector<dem::RockTemplate> read_rock_templates(const std::string& library_dir) {
  const fs::path csv = fs::path(library_dir) / "library.csv";
  std::ifstream in;
  const std::vector<std::string> head = open_library_csv(csv, in);
  std::string line;
  auto column = [&](const std::string& name) {
    const auto it = std::find(head.begin(), head.end(), name);
    if (it == head.end())
      throw InvalidInput(csv.string() + ": column " + name + " missing (not a clump library?)");
    return static_cast<std::size_t>(it - head.begin());
  };
  const std::size_t c_id = column("id"), c_w = column("W"), c_v = column("clump_volume");
  const std::size_t c_i[3] = {column("I1"), column("I2"), column("I3")};
  std::vector<dem::RockTemplate> out;
  int row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (line.empty()) continue;
    const std::vector<std::string> cells = split(line);
    if (cells.size() != head.size())
      throw InvalidInput(csv.string() + ": line " + std::to_string(row) + " has " +
                         std::to_string(cells.size()) + " fields, header " +
                         std::to_string(head.size()));
    dem::RockTemplate t;
    t.sieve_size = std::strtod(cells[c_w].c_str(), nullptr);
    ClumpTemplate& clump = t.clump;
    clump.mass.volume = std::strtod(cells[c_v].c_str(), nullptr);
    if (!(t.sieve_size > 0) || !(clump.mass.volume > 0) || !std::isfinite(t.sieve_size) ||
        !std::isfinite(clump.mass.volume))
      throw InvalidInput(csv.string() + ": line " + std::to_string(row) +
                         ": W and clump_volume must be positive, got " + cells[c_w] + " and " +
                         cells[c_v]);
    for (int a = 0; a < 3; ++a) {
      clump.principal_moments[a] = std::strtod(cells[c_i[a]].c_str(), nullptr);
      if (!(clump.principal_moments[a] > 0) || !std::isfinite(clump.principal_moments[a]))
        throw InvalidInput(csv.string() + ": line " + std::to_string(row) + ": I" +
                           std::to_string(a + 1) + " must be positive, got " + cells[c_i[a]]);
    }
    clump.mass.inertia = clump.principal_moments.asDiagonal();
    char stem[16];
    std::snprintf(stem, sizeof stem, "%05d", std::atoi(cells[c_id].c_str()));
    clump.spheres =
        read_clump(
            (fs::path(library_dir) / "particles" / (std::string(stem) + ".template.csv")).string())
            .spheres;
    out.push_back(std::move(t));
  }
  if (out.empty()) throw InvalidInput(csv.string() + ": the clump library holds no particles");
  return out;
}

std::vector<double> read_library_column(const std::string& library_dir, const std::string& name) {
  const fs::path csv = fs::path(library_dir) / "library.csv";
  std::ifstream in;
  const std::vector<std::string> head = open_library_csv(csv, in);
  std::string line;
  const auto it = std::find(head.begin(), head.end(), name);
  if (it == head.end())
    throw InvalidInput(csv.string() + ": column " + name +
                       " missing (a library of an older clumpkit; build it again)");
  const std::size_t c = static_cast<std::size_t>(it - head.begin());
  std::vector<double> out;
  int row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (line.empty()) continue;
    const std::vector<std::string> cells = split(line);
    const double v = c < cells.size() ? std::strtod(cells[c].c_str(), nullptr) : NAN;
    if (!(v > 0) || !std::isfinite(v))
      throw InvalidInput(csv.string() + ": line " + std::to_string(row) + ": " + name +
                         " must be positive, got '" + (c < cells.size() ? cells[c] : "") + "'");
    out.push_back(v);
  }
  return out;
}

dem::SpecimenSpec specimen_spec(const SpecimenRecipe& r, std::vector<dem::RockTemplate> templates) {
  dem::SpecimenSpec s;
  s.radius = 0.5 * r.container_diameter;
  s.height = r.container_height;
  s.layers = r.layers;
  s.soil_density = r.soil_density;
  s.rock_density = r.rock_density;
  s.contact = dem::deposition_contact();
  s.contact.kn = r.kn;
  s.contact.ks = r.ks;
  s.contact.friction = r.friction;
  s.contact.damping_ratio = r.damping_ratio;
  s.contact.local_damping = r.local_damping;
  if (r.linear_scaling) {
    s.contact.scaling = dem::StiffnessScaling::linear;
    s.contact.d_ref = r.d_ref;
  }
  s.target_relative_density = r.target_relative_density;
  s.calibration_frictions = r.calibration_frictions;
  s.seed = r.seed;
  s.templates = std::move(templates);
  std::vector<dem::SieveClass> gradation;
  for (const SizeClass& c : r.classes) gradation.push_back({c.min, c.max, c.percent});
  s.classes =
      dem::replace_fines(gradation, r.fines_below, r.fines_min, r.fines_max, r.soil_rock_threshold);
  return s;
}

dem::CompressionSpec compression_spec(const SpecimenRecipe& r,
                                      std::vector<dem::RockTemplate> templates) {
  const dem::SpecimenSpec s = specimen_spec(r, std::move(templates));
  dem::CompressionSpec c;
  c.shape = r.cuboid ? dem::CompressionSpec::Shape::cuboid : dem::CompressionSpec::Shape::cylinder;
  c.size = r.cuboid ? Vec3(r.container_size[0], r.container_size[1], r.container_size[2])
                    : Vec3(r.container_diameter, r.container_diameter, r.container_height);
  c.porosity = r.compression_porosity;
  c.friction = r.compression_friction;
  c.classes = s.classes;
  c.templates = s.templates;
  c.soil_density = r.soil_density;
  c.rock_density = r.rock_density;
  c.contact = s.contact;
  c.seed = r.seed;
  return c;
}

std::vector<SpecimenBody> specimen_bodies(const dem::World& world) {
  std::vector<SpecimenBody> out;
  const auto& bodies = world.bodies();
  out.reserve(bodies.size());
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const dem::Body& b = bodies[k];
    SpecimenBody s;
    s.id = static_cast<long>(k + 1);
    s.kind = b.kind;
    s.template_id = b.template_id;
    s.position = b.position;
    s.orientation = b.orientation;
    s.mass = b.mass;
    s.volume = b.volume;
    s.scale = b.scale;
    s.moments = b.moments;
    s.spheres.reserve(b.spheres.size());
    for (const Sphere& sp : b.spheres)
      s.spheres.push_back({b.orientation * sp.center + b.position, sp.radius});
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<Sphere> body_frame_spheres(const SpecimenBody& body) {
  std::vector<Sphere> out;
  out.reserve(body.spheres.size());
  const Eigen::Quaterniond inverse = body.orientation.conjugate();
  for (const Sphere& s : body.spheres)
    out.push_back({inverse * (s.center - body.position), s.radius});
  return out;
}

dem::Body dem_body(const SpecimenBody& b) {
  dem::Body body;
  body.spheres = body_frame_spheres(b);
  body.mass = b.mass;
  body.moments = b.moments;
  body.volume = b.volume;
  body.kind = b.kind;
  body.template_id = b.template_id;
  body.scale = b.scale;
  body.position = b.position;
  body.orientation = b.orientation;
  return body;
}

void write_specimen_csv(const std::string& path, const std::vector<SpecimenBody>& bodies) {
  write_file_atomically(path, [&](std::ostream& o) {
    o << "# clumpkit specimen format " << kSpecimenCsvFormat
      << ", SI units, world frame (x_world = q x_body + position). Bodies, then their spheres.\n"
         "# I1,I2,I3: principal moments (kg m2) about the body frame axes (the template's "
         "principal frame); scale: template length scale (1 for soil)\n# bodies\n";
    o << "body,kind,template,x,y,z,qw,qx,qy,qz,mass,volume,scale,I1,I2,I3\n";
    for (const SpecimenBody& b : bodies) {
      o << b.id << "," << dem::kind_name(b.kind) << "," << b.template_id << ","
        << format_number(b.position.x()) << "," << format_number(b.position.y()) << ","
        << format_number(b.position.z()) << "," << format_number(b.orientation.w()) << ","
        << format_number(b.orientation.x()) << "," << format_number(b.orientation.y()) << ","
        << format_number(b.orientation.z()) << "," << format_number(b.mass) << ","
        << format_number(b.volume) << "," << format_number(b.scale) << ","
        << format_number(b.moments.x()) << "," << format_number(b.moments.y()) << ","
        << format_number(b.moments.z()) << "\n";
    }
    o << "# spheres\nsphere,body,x,y,z,r\n";
    std::size_t n = 0;
    for (const SpecimenBody& b : bodies)
      for (const Sphere& s : b.spheres)
        o << ++n << "," << b.id << "," << format_number(s.center.x()) << ","
          << format_number(s.center.y()) << "," << format_number(s.center.z()) << ","
          << format_number(s.radius) << "\n";
  });
}

std::vector<SpecimenBody> read_specimen_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open specimen file");
  std::vector<SpecimenBody> bodies;
  std::string line;
  long line_no = 0;
  auto bad = [&](const std::string& why) {
    throw InvalidInput(path + ":" + std::to_string(line_no) + ": " + why);
  };
  auto number = [&](const std::string& cell, const char* field) {
    char* end = nullptr;
    const double v = std::strtod(cell.c_str(), &end);
    if (cell.empty() || *end != '\0' || !std::isfinite(v))
      bad("field " + std::string(field) + ": not a finite number: '" + cell + "'");
    return v;
  };
  auto integer = [&](const std::string& cell, const char* field) {
    const double v = number(cell, field);
    if (v != std::floor(v)) bad("field " + std::string(field) + ": not an integer: '" + cell + "'");
    // Ids and counts index memory: beyond 2^53 they are not even exact doubles.
    if (!(std::abs(v) <= 9007199254740992.0))
      bad("field " + std::string(field) + ": integer out of range: '" + cell + "'");
    return static_cast<long>(v);
  };
  const std::string format_line =
      "# clumpkit specimen format " + std::to_string(kSpecimenCsvFormat);
  enum class Section { head, bodies, spheres } section = Section::head;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_no == 1 && line.rfind(format_line + ",", 0) != 0)
      bad("not a clumpkit specimen.csv of format " + std::to_string(kSpecimenCsvFormat) +
          " (first line '" + line.substr(0, 40) + "')");
    if (line.empty()) continue;
    if (line == "# bodies") {
      section = Section::bodies;
      continue;
    }
    if (line == "# spheres") {
      section = Section::spheres;
      continue;
    }
    if (line[0] == '#' || line.rfind("body,", 0) == 0 || line.rfind("sphere,", 0) == 0) continue;
    const std::vector<std::string> c = split(line);
    if (section == Section::bodies) {
      if (c.size() != 16) bad("a body row has 16 fields, found " + std::to_string(c.size()));
      SpecimenBody b;
      b.id = integer(c[0], "body");
      if (b.id != static_cast<long>(bodies.size()) + 1)
        bad("field body: expected id " + std::to_string(bodies.size() + 1) + ", found " + c[0]);
      if (c[1] == "rock")
        b.kind = dem::BodyKind::rock;
      else if (c[1] == "soil")
        b.kind = dem::BodyKind::soil;
      else
        bad("field kind: expected rock or soil, found '" + c[1] + "'");
      const long template_id = integer(c[2], "template");
      if (template_id < -1 || template_id > 2147483647L)
        bad("field template: out of range: '" + c[2] + "'");
      b.template_id = static_cast<int>(template_id);
      b.position = Vec3(number(c[3], "x"), number(c[4], "y"), number(c[5], "z"));
      b.orientation = Eigen::Quaterniond(number(c[6], "qw"), number(c[7], "qx"), number(c[8], "qy"),
                                         number(c[9], "qz"));
      if (std::abs(b.orientation.norm() - 1.0) > 1e-9)
        bad("fields qw..qz: not a unit quaternion (norm " +
            format_number(b.orientation.norm(), 12) + ")");
      b.mass = number(c[10], "mass");
      b.volume = number(c[11], "volume");
      b.scale = number(c[12], "scale");
      b.moments = Vec3(number(c[13], "I1"), number(c[14], "I2"), number(c[15], "I3"));
      if (!(b.mass > 0) || !(b.volume > 0) || !(b.scale > 0) || !(b.moments.minCoeff() > 0))
        bad("fields mass, volume, scale, I1..I3 must be positive");
      bodies.push_back(std::move(b));
    } else if (section == Section::spheres) {
      if (c.size() != 6) bad("a sphere row has 6 fields, found " + std::to_string(c.size()));
      const long body = integer(c[1], "body");
      if (body < 1 || body > static_cast<long>(bodies.size())) bad("field body: no body " + c[1]);
      const Sphere sphere{Vec3(number(c[2], "x"), number(c[3], "y"), number(c[4], "z")),
                          number(c[5], "r")};
      if (!(sphere.radius > 0)) bad("field r: radius must be positive, found " + c[5]);
      bodies[static_cast<std::size_t>(body - 1)].spheres.push_back(sphere);
    } else {
      bad("a data row before the '# bodies' section");
    }
  }
  if (line_no == 0) throw InvalidInput(path + ": empty specimen file");
  for (const SpecimenBody& b : bodies)
    if (b.spheres.empty())
      throw InvalidInput(path + ": body " + std::to_string(b.id) + " has no spheres");
  return bodies;
}

void write_specimen_vtp(const std::string& path, const std::vector<SpecimenBody>& bodies) {
  write_file_atomically(path, [&](std::ostream& o) {
    std::size_t n = 0;
    for (const SpecimenBody& b : bodies) n += b.spheres.size();
    o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
         "byte_order=\"LittleEndian\">\n<PolyData>\n<Piece NumberOfPoints=\""
      << n << "\" NumberOfVerts=\"" << n << "\">\n<Points>\n"
      << "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const SpecimenBody& b : bodies)
      for (const Sphere& s : b.spheres)
        o << format_number(s.center.x()) << " " << format_number(s.center.y()) << " "
          << format_number(s.center.z()) << "\n";
    o << "</DataArray>\n</Points>\n<PointData Scalars=\"radius\">\n"
      << "<DataArray type=\"Float64\" Name=\"radius\" format=\"ascii\">\n";
    for (const SpecimenBody& b : bodies)
      for (const Sphere& s : b.spheres) o << format_number(s.radius) << "\n";
    o << "</DataArray>\n<DataArray type=\"Int32\" Name=\"body\" format=\"ascii\">\n";
    for (const SpecimenBody& b : bodies)
      for (std::size_t s = 0; s < b.spheres.size(); ++s) o << b.id << "\n";
    o << "</DataArray>\n<DataArray type=\"Int32\" Name=\"kind\" format=\"ascii\">\n";
    for (const SpecimenBody& b : bodies)
      for (std::size_t s = 0; s < b.spheres.size(); ++s)
        o << (b.kind == dem::BodyKind::rock ? 1 : 0) << "\n";
    o << "</DataArray>\n</PointData>\n<Verts>\n"
      << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < n; ++k) o << k << "\n";
    o << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < n; ++k) o << k + 1 << "\n";
    o << "</DataArray>\n</Verts>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  });
}

void write_calibration_csv(const std::string& path, const dem::SpecimenResult& result) {
  write_file_atomically(path, [&](std::ostream& o) {
    o << "friction,porosity,void_ratio,relative_density,steps,stopped_by\n";
    for (const dem::CalibrationPoint& p : result.calibration)
      o << format_number(p.friction) << "," << format_number(p.porosity) << ","
        << format_number(p.void_ratio) << ","
        << format_number(
               dem::relative_density(p.porosity, result.porosity_max, result.porosity_min))
        << "," << p.steps << "," << p.stopped_by << "\n";
  });
}

void write_calibration_plot(const std::string& path, const dem::SpecimenResult& result,
                            double target_relative_density) {
  PlotSeries measured, target, chosen;
  measured.label = "porosity after compaction at friction mu";
  measured.marker = 4;
  double fmax = 0;
  for (const dem::CalibrationPoint& p : result.calibration) {
    measured.points.x.push_back(p.friction);
    measured.points.y.push_back(p.porosity);
    fmax = std::max(fmax, p.friction);
  }
  if (!(fmax > 0)) fmax = 1;
  target.points = {{0.0, fmax}, {result.target_porosity, result.target_porosity}};
  target.label = "target Dr " + format_fixed(target_relative_density, 2) +
                 ": n = " + format_fixed(result.target_porosity, 4);
  target.rgb = {150, 150, 150};
  chosen.points = {{result.friction_compaction}, {result.target_porosity}};
  chosen.label = "chosen mu* = " + format_fixed(result.friction_compaction, 3);
  chosen.rgb = {210, 30, 30};
  chosen.line = false;
  chosen.marker = 6;
  write_plot(path, {target, measured, chosen}, "friction coefficient during compaction, mu (-)",
             "porosity n (-)", "clumpkit specimen: calibration of porosity against friction");
}

std::vector<std::string> write_slices(const std::string& dir, const dem::SpecimenResult& result,
                                      double radius, const std::vector<double>& heights,
                                      int pixels) {
  fs::create_directories(dir);
  std::vector<std::string> names;
  const double scale = pixels / (2.0 * radius);  // pixels per metre
  for (double z : heights) {
    cv::Mat img(pixels, pixels, CV_8UC3, cv::Scalar(255, 255, 255));
    auto to_px = [&](double x, double y) {
      return cv::Point(static_cast<int>(std::lround((x + radius) * scale * 16)),
                       static_cast<int>(std::lround((radius - y) * scale * 16)));
    };
    for (const dem::Body& b : result.world.bodies()) {
      const bool rock = b.kind == dem::BodyKind::rock;
      for (const Sphere& s : b.spheres) {
        const Vec3 c = b.orientation * s.center + b.position;
        const double dz = z - c.z(), r2 = s.radius * s.radius - dz * dz;
        if (r2 <= 0) continue;
        const int r = static_cast<int>(std::lround(std::sqrt(r2) * scale * 16));
        cv::circle(img, to_px(c.x(), c.y()), r,
                   rock ? cv::Scalar(40, 40, 210) : cv::Scalar(200, 90, 30), cv::FILLED,
                   cv::LINE_AA, 4);
      }
    }
    cv::circle(img, to_px(0, 0), static_cast<int>(std::lround(radius * scale * 16)) - 16,
               cv::Scalar(120, 120, 120), 1, cv::LINE_AA, 4);
    char name[64];
    std::snprintf(name, sizeof name, "z%05.0fmm.png", z * 1000.0);
    cv::putText(img,
                std::string("z = ") + std::to_string(static_cast<int>(std::lround(z * 1000))) +
                    " mm  (rock red, soil blue)",
                cv::Point(8, 18), cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0));
    cv::Mat rgb;
    cv::cvtColor(img, rgb, cv::COLOR_BGR2RGB);
    write_png((fs::path(dir) / name).string(), rgb.cols, rgb.rows, 3, rgb.ptr<std::uint8_t>(0),
              rgb.step);
    names.push_back(name);
  }
  return names;
}

namespace {

// The contact law as report.json records it (the test command and the exports read it back).
nlohmann::ordered_json contact_json(const SpecimenRecipe& recipe) {
  nlohmann::ordered_json c = {{"kn", recipe.kn},
                              {"ks", recipe.ks},
                              {"friction", recipe.friction},
                              {"damping_ratio", recipe.damping_ratio},
                              {"local_damping", recipe.local_damping},
                              {"stiffness_scaling", recipe.linear_scaling ? "linear" : "none"}};
  if (recipe.linear_scaling) c["d_ref"] = recipe.d_ref;
  return c;
}

nlohmann::ordered_json report_head(const SpecimenRecipe& recipe) {
  nlohmann::ordered_json j;
  j["recipe"] = recipe.path;
  j["seed"] = recipe.seed;
  return j;
}

// bodies, rocks, soil and spheres of a built specimen.
void add_counts(nlohmann::ordered_json& j, const dem::World& world) {
  std::size_t spheres = 0, rocks = 0;
  for (const dem::Body& b : world.bodies()) {
    spheres += b.spheres.size();
    rocks += b.kind == dem::BodyKind::rock;
  }
  j["bodies"] = world.bodies().size();
  j["rocks"] = rocks;
  j["soil"] = world.bodies().size() - rocks;
  j["spheres"] = spheres;
}

}  // namespace

nlohmann::ordered_json specimen_report(const SpecimenRecipe& recipe, const dem::SpecimenResult& r) {
  nlohmann::ordered_json j = report_head(recipe);
  j["porosity"] = r.porosity;
  j["relative_density"] = r.relative_density;
  j["target_relative_density"] = recipe.target_relative_density;
  j["target_porosity"] = r.target_porosity;
  j["porosity_max"] = r.porosity_max;
  j["porosity_min"] = r.porosity_min;
  j["friction_compaction"] = r.friction_compaction;
  j["friction"] = recipe.friction;
  j["container"] = {{"diameter", recipe.container_diameter}, {"height", recipe.container_height}};
  j["density"] = {{"rock", recipe.rock_density}, {"soil", recipe.soil_density}};
  j["contact"] = contact_json(recipe);
  j["height"] = r.height;
  j["layer_height"] = r.layer_height;
  j["layer_porosity_compacted"] = r.layer_porosity_compacted;
  add_counts(j, r.world);
  j["layer_porosity"] = r.layer_porosity;
  double lo = 1, hi = 0;
  for (double n : r.layer_porosity) lo = std::min(lo, n), hi = std::max(hi, n);
  j["layer_porosity_spread"] = hi - lo;
  j["band_porosity"] = r.band_porosity;
  j["coordination_number"] = r.coordination;
  j["measurement_region"] = {{"radius", r.region.radius},
                             {"z_lo", r.region.z_lo},
                             {"z_hi", r.region.z_hi},
                             {"method",
                              "exact sphere-region volumes (union of each body's "
                              "spheres, slice areas integrated over z)"}};
  nlohmann::ordered_json cal = nlohmann::ordered_json::array();
  for (const auto& p : r.calibration)
    cal.push_back({{"friction", p.friction},
                   {"porosity", p.porosity},
                   {"steps", p.steps},
                   {"stopped_by", p.stopped_by}});
  j["calibration"] = cal;
  nlohmann::ordered_json rounds = nlohmann::ordered_json::array();
  for (const auto& x : r.rounds)
    rounds.push_back({{"friction_compaction", x.friction},
                      {"porosity", x.porosity},
                      {"relative_density", x.relative_density}});
  j["rounds"] = rounds;
  j["timestep"] = r.world.options().timestep;
  j["density_scaling"] = r.density_scaling;
  nlohmann::ordered_json steps, seconds;
  for (const auto& [k, v] : r.steps) steps[k] = v;
  for (const auto& [k, v] : r.seconds) seconds[k] = v;
  j["steps"] = steps;
  j["seconds"] = seconds;
  return j;
}

nlohmann::ordered_json compression_report(const SpecimenRecipe& recipe,
                                          const dem::CompressionResult& r) {
  nlohmann::ordered_json j = report_head(recipe);
  j["method"] = "compression";
  j["porosity"] = r.porosity;
  j["target_porosity"] = recipe.compression_porosity;
  j["friction_compression"] = recipe.compression_friction;
  j["friction"] = recipe.friction;
  if (recipe.cuboid)
    j["container"] = {{"shape", "cuboid"},
                      {"size", {r.hi.x() - r.lo.x(), r.hi.y() - r.lo.y(), r.hi.z() - r.lo.z()}},
                      {"lo", {r.lo.x(), r.lo.y(), r.lo.z()}},
                      {"hi", {r.hi.x(), r.hi.y(), r.hi.z()}}};
  else
    j["container"] = {{"shape", "cylinder"}, {"diameter", 2 * r.radius}, {"height", r.height}};
  j["density"] = {{"rock", recipe.rock_density}, {"soil", recipe.soil_density}};
  j["contact"] = contact_json(recipe);
  j["height"] = r.height;
  add_counts(j, r.world);
  j["coordination_number"] = r.coordination;
  j["mean_stress"] = r.mean_stress;
  j["gravity"] = false;
  j["timestep"] = r.timestep;
  j["steps"] = {{"compression", r.compression_steps}, {"relaxation", r.relax_steps}};
  j["relaxed_by"] = r.relaxed_by;
  return j;
}

}  // namespace clumpkit
