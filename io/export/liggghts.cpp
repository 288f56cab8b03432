#include "io/export/liggghts.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/units.h"

#include <cmath>
#include <functional>
#include <map>
#include <utility>

namespace clumpkit {

namespace {

/// Distinct primes above 10,000, one per call (LIGGGHTS's seeds must be such primes).
class Primes {
 public:
  long next() {
    for (++last_;; ++last_) {
      bool prime = true;
      for (long d = 2; d * d <= last_ && prime; ++d) prime = last_ % d != 0;
      if (prime) return last_;
    }
  }

 private:
  long last_ = 10000;
};

/// "v v v v" for a 2-type peratomtypepair property with one value.
std::string pairs(double v) {
  const std::string s = format_number(v);
  return s + " " + s + " " + s + " " + s;
}

/// Template number of each distinct (template, scale) pair of the rock bodies.
using TemplateIds = std::map<std::pair<int, double>, int>;

/// templates.liggghts: one multisphere template and distribution per distinct template.
void write_liggghts_templates(std::ostream& o, const std::vector<SpecimenBody>& bodies,
                              const TemplateIds& template_of, Primes& primes) {
  o << "# clumpkit clump templates (SI): spheres in the principal frame, centroid at the\n"
       "# origin; mass and inertia_tensor (Ixx Ixy Ixz Iyy Iyz Izz) are clumpkit's exact ones,\n"
       "# taken as given with use_density. volume_limit lifts LIGGGHTS's 1e-12 m3 floor on a\n"
       "# template's volume (sub-millimetre grains).\n";
  int written = 0;
  for (const SpecimenBody& b : bodies) {
    if (b.kind != dem::BodyKind::rock) continue;
    const int k = template_of.at({b.template_id, b.scale});
    if (k <= written) continue;
    written = k;
    o << "fix pt" << k << " all particletemplate/multisphere " << primes.next()
      << " atom_type 1 volume_limit 1e-40 density constant " << format_number(b.mass / b.volume)
      << " nspheres " << b.spheres.size() << " ntry 100000 spheres &\n";
    for (const Sphere& s : body_frame_spheres(b))
      o << "    " << format_xyz(s.center) << " " << format_number(s.radius) << " &\n";
    o << "    type " << k << " mass " << format_number(b.mass) << " inertia_tensor "
      << format_number(b.moments.x()) << " 0 0 " << format_number(b.moments.y()) << " 0 "
      << format_number(b.moments.z()) << " use_density\n"
      << "fix pdd" << k << " all particledistribution/discrete " << primes.next() << " 1 pt" << k
      << " 1.0\n";
  }
}

/// specimen_bodies.liggghts: one point region and one insertion per rock body.
void write_liggghts_insertions(std::ostream& o, const std::vector<SpecimenBody>& bodies,
                               const TemplateIds& template_of, const SpecimenExtents& e,
                               Primes& primes) {
  o << "# clumpkit rock bodies: one point region and one insertion per body, at its centroid\n"
       "# with its quaternion (w x y z: template frame to world).\n";
  for (const SpecimenBody& b : bodies) {
    if (b.kind != dem::BodyKind::rock) continue;
    // A point region: insert/pack draws the position inside it (1e-9 of the smallest radius).
    const double eps = 1e-9 * e.r_min;
    o << "region cb" << b.id << " block " << format_number(b.position.x() - eps) << " "
      << format_number(b.position.x() + eps) << " " << format_number(b.position.y() - eps) << " "
      << format_number(b.position.y() + eps) << " " << format_number(b.position.z() - eps) << " "
      << format_number(b.position.z() + eps) << " units box volume_limit 1e-300\n"
      << "fix ins" << b.id << " rock insert/pack seed " << primes.next()
      << " distributiontemplate pdd" << template_of.at({b.template_id, b.scale})
      << " insert_every once overlapcheck no all_in no orientation constant "
      << format_number(b.orientation.w()) << " " << format_number(b.orientation.x()) << " "
      << format_number(b.orientation.y()) << " " << format_number(b.orientation.z()) << " region cb"
      << b.id << " particles_in_region 1\n";
  }
}

/// soil.liggghts: one atom per soil body.
void write_liggghts_soil(std::ostream& o, const std::vector<SpecimenBody>& bodies) {
  o << "# clumpkit soil spheres: atom ids 1.. in body order\n";
  long atom = 0;
  for (const SpecimenBody& b : bodies) {
    if (b.kind != dem::BodyKind::soil) continue;
    const Sphere& s = b.spheres.front();
    o << "create_atoms 2 single " << format_xyz(s.center) << " units box\n"
      << "set atom " << ++atom << " diameter " << format_number(2 * s.radius) << " density "
      << format_number(b.mass / b.volume) << "\n";
  }
}

/// bodies_map.csv: the LIGGGHTS atom or multisphere body of each specimen body.
void write_liggghts_body_map(std::ostream& o, const std::vector<SpecimenBody>& bodies,
                             std::size_t soils) {
  o << "# specimen.csv body id -> LIGGGHTS ids: soil atom id, or rock multisphere body id and\n"
       "# its first atom id (atoms of a body are consecutive)\n"
    << csv_header("bodies_map", "body,liggghts_kind,liggghts_id,first_atom", si_length()) << "\n";
  long atom = static_cast<long>(soils), body = 0, soil = 0;
  for (const SpecimenBody& b : bodies)
    if (b.kind == dem::BodyKind::soil) {
      ++soil;
      o << b.id << ",atom," << soil << "," << soil << "\n";
    } else {
      o << b.id << ",multisphere," << ++body << "," << atom + 1 << "\n";
      atom += static_cast<long>(b.spheres.size());
    }
}

/// in.clumpkit: the deck that inserts the specimen and settles it under gravity.
void write_liggghts_deck(std::ostream& o, const EngineSettings& settings, const SpecimenExtents& e,
                         std::size_t rocks, std::size_t soils) {
  const dem::ContactParams& c = settings.contact;
  // Dashpot: clumpkit's c = 2β·sqrt(m_eff·kn) becomes γn = c/m_eff (hooke/stiffness multiplies
  // γn by each pair's m_eff) at the median body's m_eff, as in the LAMMPS deck.
  const double m_eff = 0.5 * e.m_median;
  const double gamma_n = 2.0 * c.damping_ratio * std::sqrt(c.kn / m_eff);
  const double dt = 0.2 * std::sqrt(e.m_min / c.kn);
  const double pad = 2 * e.r_max;
  const double half = settings.container_radius + pad;
  const double z_hi = std::max(settings.container_height, e.top) + pad;
  const std::string model = "model hooke/stiffness tangential history";
  o << "# clumpkit export for LIGGGHTS-PUBLIC 3.8 (Debian 12 `liggghts`): the specimen with\n"
       "# clumpkit's exact clump masses and inertia tensors (templates.liggghts), each body\n"
       "# inserted at its pose, settled under gravity in its container. Serial:\n"
       "#   liggghts -in in.clumpkit [-var nsteps N]   (stdbuf -o0 shows errors before aborts)\n"
    << "variable nsteps index 1000\n"
    << "atom_style sphere\n"
       "atom_modify map array\n"
       "boundary f f f\n"
       "newton off\n"
       "communicate single vel yes\n"
       "units si\n"
    << "region domain block " << format_number(-half) << " " << format_number(half) << " "
    << format_number(-half) << " " << format_number(half) << " " << format_number(-pad) << " "
    << format_number(z_hi) << " units box\n"
    << "create_box 2 domain\n"
    << "neighbor " << format_number(0.5 * e.r_min) << " bin\n"
    << "neigh_modify delay 0\n"
    << "fix m1 all property/global kn peratomtypepair 2 " << pairs(c.kn) << "\n"
    << "fix m2 all property/global kt peratomtypepair 2 " << pairs(c.ks) << "\n"
    << "fix m3 all property/global gamman peratomtypepair 2 " << pairs(gamma_n) << "\n"
    << "fix m4 all property/global gammat peratomtypepair 2 " << pairs(0) << "\n"
    << "fix m5 all property/global coefficientFriction peratomtypepair 2 " << pairs(c.friction)
    << "\n"
    << "pair_style gran " << model << "\n"
    << "pair_coeff * *\n"
    << "timestep " << format_number(dt) << "\n"
    << "fix grav all gravity " << format_number(settings.gravity) << " vector 0.0 0.0 -1.0\n"
    << "fix floor all wall/gran " << model << " primitive type 1 zplane 0.0\n"
    << "fix cyl all wall/gran " << model << " primitive type 1 zcylinder "
    << format_number(settings.container_radius) << " 0.0 0.0\n"
    << "group rock type 1\n";
  if (soils > 0) o << "include soil.liggghts\n";
  o << "group soil type 2\n";
  if (rocks > 0)
    o << "include templates.liggghts\n"
         "fix ms all multisphere\n"
         "include specimen_bodies.liggghts\n";
  o << "compute ke all ke/multisphere\n"
       "compute rke all erotate/multisphere\n"
       "thermo_style custom step atoms c_ke c_rke\n"
       "thermo_modify lost ignore norm no\n"
       "thermo 100\n"
       "# Step 1 inserts the bodies (after the position update, so they stand where clumpkit\n"
       "# put them); the soil is integrated from step 2 on, so after step 1 every sphere is at\n"
       "# the specimen's position.\n"
       "run 1\n"
       "# the atoms after the insertion step, and at the end (run 0 writes a dump once)\n"
       "dump d1 all custom 1 atoms.1.txt id type x y z radius\n"
       "dump_modify d1 sort id format \"%d %d %.17g %.17g %.17g %.17g\"\n"
       "run 0\n"
       "undump d1\n"
       "fix integr soil nve/sphere\n"
       "run ${nsteps}\n"
       "dump d2 all custom 1 atoms.end.txt id type x y z radius\n"
       "dump_modify d2 sort id format \"%d %d %.17g %.17g %.17g %.17g\"\n"
       "run 0\n";
}

}  // namespace

std::vector<std::string> write_liggghts_export(const std::vector<SpecimenBody>& bodies,
                                               const EngineSettings& settings,
                                               const std::string& dir) {
  if (bodies.empty()) throw InvalidInput("LIGGGHTS export: the specimen has no bodies");
  const SpecimenExtents e = specimen_extents(bodies);
  std::vector<std::string> files;
  auto file = [&](const char* name, const std::function<void(std::ostream&)>& fill) {
    files.push_back(write_export_file(dir, name, fill));
  };
  Primes primes;

  // Templates: one per distinct (template, scale) pair, numbered from 1 in body order.
  TemplateIds template_of;
  std::size_t rocks = 0, soils = 0;
  for (const SpecimenBody& b : bodies) {
    if (b.kind != dem::BodyKind::rock) {
      ++soils;
      continue;
    }
    ++rocks;
    template_of.emplace(std::make_pair(b.template_id, b.scale),
                        static_cast<int>(template_of.size()) + 1);
  }
  file("templates.liggghts",
       [&](std::ostream& o) { write_liggghts_templates(o, bodies, template_of, primes); });
  file("specimen_bodies.liggghts",
       [&](std::ostream& o) { write_liggghts_insertions(o, bodies, template_of, e, primes); });
  file("soil.liggghts", [&](std::ostream& o) { write_liggghts_soil(o, bodies); });
  file("bodies_map.csv", [&](std::ostream& o) { write_liggghts_body_map(o, bodies, soils); });
  file("in.clumpkit", [&](std::ostream& o) { write_liggghts_deck(o, settings, e, rocks, soils); });
  return files;
}

}  // namespace clumpkit
