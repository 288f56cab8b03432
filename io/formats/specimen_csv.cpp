#include "io/formats/specimen_csv.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/atomic_file.h"
#include "io/base/text.h"
#include "io/base/units.h"

#include <cmath>
#include <fstream>
#include <optional>

namespace clumpkit {

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
    s.zone = b.zone;
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
  body.zone = b.zone;
  body.position = b.position;
  body.orientation = b.orientation;
  return body;
}

void write_specimen_csv(const std::string& path, const std::vector<SpecimenBody>& bodies) {
  write_file_atomically(path, [&](std::ostream& o) {
    o << "# clumpkit specimen format " << kSpecimenCsvFormat
      << ", SI units, world frame (x_world = q x_body + position). Bodies, then their spheres.\n"
         "# I1,I2,I3: principal moments (kg m2) about the body frame axes (the template's "
         "principal frame); scale: template length scale (1 for soil); zone: region of a zoned "
         "specimen (0 without zones)\n# bodies\n";
    o << csv_header("specimen",
                    "body,kind,template,x,y,z,qw,qx,qy,qz,mass,volume,scale,I1,I2,I3,zone",
                    si_length())
      << "\n";
    for (const SpecimenBody& b : bodies) {
      o << b.id << "," << dem::kind_name(b.kind) << "," << b.template_id << ","
        << format_number(b.position.x()) << "," << format_number(b.position.y()) << ","
        << format_number(b.position.z()) << "," << format_number(b.orientation.w()) << ","
        << format_number(b.orientation.x()) << "," << format_number(b.orientation.y()) << ","
        << format_number(b.orientation.z()) << "," << format_number(b.mass) << ","
        << format_number(b.volume) << "," << format_number(b.scale) << ","
        << format_number(b.moments.x()) << "," << format_number(b.moments.y()) << ","
        << format_number(b.moments.z()) << "," << b.zone << "\n";
    }
    o << "# spheres\n" << csv_header("specimen", "sphere,body,x,y,z,r", si_length()) << "\n";
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
  LineReader at{path};
  long& line_no = at.line;
  auto bad = [&](const std::string& why) { at.fail(why); };
  auto number = [&](const std::string& cell, const char* field) { return at.number(cell, field); };
  auto integer = [&](const std::string& cell, const char* field) {
    const double v = number(cell, field);
    if (v != std::floor(v)) bad("field " + std::string(field) + ": not an integer: '" + cell + "'");
    // Ids and counts index memory: beyond 2^53 they are not even exact doubles.
    if (!(std::abs(v) <= 9007199254740992.0))
      bad("field " + std::string(field) + ": integer out of range: '" + cell + "'");
    return static_cast<long>(v);
  };
  // Format 3 had no zone column: still read, every body in zone 0.
  const std::string format_line = "# clumpkit specimen format ";
  std::size_t body_fields = 17;
  enum class Section { head, bodies, spheres } section = Section::head;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_no == 1) {
      const bool v4 = line.rfind(format_line + std::to_string(kSpecimenCsvFormat) + ",", 0) == 0;
      if (!v4 && line.rfind(format_line + "3,", 0) != 0)
        bad("not a clumpkit specimen.csv of format " + std::to_string(kSpecimenCsvFormat) +
            " or 3 (first line '" + line.substr(0, 40) + "')");
      body_fields = v4 ? 17 : 16;
    }
    if (line.empty()) continue;
    if (line == "# bodies") {
      section = Section::bodies;
      continue;
    }
    if (line == "# spheres") {
      section = Section::spheres;
      continue;
    }
    if (line[0] == '#') continue;
    const std::vector<std::string> c = split_csv(line);
    // A section's header, with units ("body[1],...") or without (files written before units).
    const std::string first = column_name(c.front());
    if (first == "body" || first == "sphere") continue;
    if (section == Section::bodies) {
      if (c.size() != body_fields)
        bad("a body row has " + std::to_string(body_fields) + " fields, found " +
            std::to_string(c.size()));
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
      if (body_fields == 17) {
        const long zone = integer(c[16], "zone");
        if (zone < 0 || zone > 1000) bad("field zone: out of range [0, 1000]: '" + c[16] + "'");
        b.zone = static_cast<int>(zone);
      }
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

}  // namespace clumpkit
