#include "io/export/pfc.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/units.h"

#include <cmath>
#include <map>
#include <utility>

namespace clumpkit {

AxisAngle axis_angle(const Eigen::Quaterniond& q) {
  Eigen::Quaterniond u = q.normalized();
  if (u.w() < 0) u.coeffs() = -u.coeffs();
  const double s = u.vec().norm();
  AxisAngle a;
  if (s == 0) return a;
  a.axis = u.vec() / s;
  a.degrees = 2 * std::atan2(s, u.w()) * 180 / M_PI;
  return a;
}

std::vector<std::string> write_pfc_export(const std::vector<SpecimenBody>& bodies,
                                          const EngineSettings& settings, const std::string& dir) {
  if (bodies.empty()) throw InvalidInput("PFC export: the specimen has no bodies");
  const SpecimenExtents e = specimen_extents(bodies);
  const dem::ContactParams& c = settings.contact;
  const double dt = 0.2 * std::sqrt(e.m_min / c.kn);
  const std::string file = write_export_file(dir, "clumpkit.p3dat", [&](std::ostream& o) {
    o << "; clumpkit export for PFC3D, syntax of PFC 7.0 (Itasca documentation); not run by\n"
         "; clumpkit's tests (no PFC licence): check keyword names against your version (PFC 5\n"
         "; differs). Units SI. Clump templates carry clumpkit's exact volume and unit-density\n"
         "; inertia (order I11 I22 I33 I12 I13 I23), so PFC does not estimate them; replicate\n"
         "; sets the density. Body ids are specimen.csv's (clump id for rock, ball id for soil).\n"
         "model new\n"
         "model large-strain on\n";
    const double half = settings.container_radius + 4 * e.r_max;
    o << "model domain extent " << format_number(-half) << " " << format_number(half) << " "
      << format_number(-half) << " " << format_number(half) << " " << format_number(-4 * e.r_max)
      << " " << format_number(std::max(settings.container_height, e.top) + 4 * e.r_max)
      << " condition destroy\n";
    // Contact law: linear model with the recipe's stiffnesses, friction and normal damping
    // ratio (PFC's dp_nratio is the same β = c / (2·sqrt(m_eff·kn))).
    o << "contact cmat default model linear property kn " << format_number(c.kn) << " ks "
      << format_number(c.ks) << " fric " << format_number(c.friction) << " dp_nratio "
      << format_number(c.damping_ratio) << "\n";

    // One template per distinct (template, scale) pair, named t<template>_<n>.
    std::map<std::pair<int, double>, std::string> names;
    for (const SpecimenBody& b : bodies) {
      if (b.kind != dem::BodyKind::rock) continue;
      const auto key = std::make_pair(b.template_id, b.scale);
      if (names.count(key)) continue;
      const std::string name =
          "t" + std::to_string(b.template_id) + "_" + std::to_string(names.size() + 1);
      names[key] = name;
      const double per_density = b.volume / b.mass;  // 1/ρ
      o << "clump template create name '" << name << "' pebbles " << b.spheres.size() << " &\n";
      for (const Sphere& s : body_frame_spheres(b))
        o << "    " << format_number(s.radius) << " " << format_xyz(s.center) << " &\n";
      o << "    volume " << format_number(b.volume) << " inertia "
        << format_number(b.moments.x() * per_density) << " "
        << format_number(b.moments.y() * per_density) << " "
        << format_number(b.moments.z() * per_density) << " 0 0 0 position 0 0 0\n";
    }
    for (const SpecimenBody& b : bodies) {
      if (b.kind == dem::BodyKind::rock) {
        const AxisAngle a = axis_angle(b.orientation);
        o << "clump replicate id " << b.id << " name '" << names[{b.template_id, b.scale}]
          << "' position " << format_xyz(b.position) << " axis " << format_xyz(a.axis) << " angle "
          << format_number(a.degrees) << " density " << format_number(b.mass / b.volume) << "\n";
      } else {
        const Sphere& s = b.spheres.front();
        o << "ball create id " << b.id << " position " << format_xyz(s.center) << " radius "
          << format_number(s.radius) << "\n";
      }
    }
    o << "ball attribute density " << format_number(settings.soil_density) << " damp "
      << format_number(c.local_damping) << "\n"
      << "clump attribute damp " << format_number(c.local_damping) << "\n"
      << "wall generate name 'floor' plane position 0 0 0 dip 0 ddir 0\n"
      << "wall generate name 'cylinder' cylinder base 0 0 0 axis 0 0 1 height "
      << format_number(std::max(settings.container_height, e.top) + 2 * e.r_max) << " radius "
      << format_number(settings.container_radius) << " cap false false\n"
      << "wall property kn " << format_number(c.kn) << " ks " << format_number(c.ks) << " fric "
      << format_number(c.friction) << "\n"
      << "model gravity 0 0 " << format_number(-settings.gravity) << "\n"
      << "model timestep fix " << format_number(dt) << "\n"
      << "fish define clumpkit_report\n"
         "  ; id, mass and principal moments of every clump as PFC sees them\n"
         "  loop foreach local cl clump.list\n"
         "    local p = clump.moi.prin(cl)\n"
         "    io.out(string(clump.id(cl)) + ' ' + string(clump.mass(cl)) + ' ' + "
         "string(p->x) + ' ' + string(p->y) + ' ' + string(p->z))\n"
         "  endloop\n"
         "end\n"
         "[clumpkit_report]\n"
         "model cycle 1000\n"
         "[clumpkit_report]\n"
         "model save 'clumpkit_settled'\n";
  });
  const std::string map = write_export_file(dir, "bodies_map.csv", [&](std::ostream& o) {
    o << "# specimen.csv body id -> PFC id: clump id (rock) or ball id (soil), the same number\n"
      << csv_header("bodies_map", "body,pfc_kind,pfc_id", si_length()) << "\n";
    for (const SpecimenBody& b : bodies)
      o << b.id << "," << (b.kind == dem::BodyKind::rock ? "clump" : "ball") << "," << b.id << "\n";
  });
  return {file, map};
}

}  // namespace clumpkit
