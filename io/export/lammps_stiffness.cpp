#include "io/export/lammps_stiffness.h"

#include "geom/errors.h"
#include "geom/format.h"

#include <algorithm>
#include <cmath>

namespace clumpkit {

namespace {

double soil_diameter(const SpecimenBody& b) {
  return 2.0 * b.spheres.front().radius;
}

}  // namespace

double lammps_dashpot(double kn, double m_eff, double beta) {
  return 2.0 * beta * std::sqrt(kn / m_eff);
}

std::string lammps_hooke_args(double kn, double kt, double gamma_n, double mu) {
  return format_number(kn) + " " + format_number(kt) + " " + format_number(gamma_n) + " 0 " +
         format_number(mu) + " 1";
}

std::vector<StiffnessClass> stiffness_classes(const std::vector<SpecimenBody>& bodies,
                                              const std::string& where, double tolerance,
                                              int max_classes) {
  std::vector<const SpecimenBody*> soil;
  for (const SpecimenBody& b : bodies) {
    if (b.kind == dem::BodyKind::rock || b.spheres.size() != 1)
      throw InvalidInput(where +
                         ": contact.stiffness_scaling: \"linear\" is exported for soil "
                         "spheres only (body " +
                         std::to_string(b.id) +
                         " is a clump: LAMMPS takes a stiffness per pair of atom types)");
    soil.push_back(&b);
  }
  std::sort(soil.begin(), soil.end(), [](const SpecimenBody* a, const SpecimenBody* b) {
    return soil_diameter(*a) < soil_diameter(*b);
  });
  std::vector<StiffnessClass> classes;
  double d_sum = 0, m_sum = 0;
  for (const SpecimenBody* b : soil) {
    const double d = soil_diameter(*b);
    if (classes.empty() || d > classes.back().d_min * (1.0 + tolerance)) {
      classes.push_back({d, 0, d, d, 0});
      d_sum = m_sum = 0;
    }
    StiffnessClass& c = classes.back();
    d_sum += d;
    m_sum += b->mass;
    c.d_max = d;
    c.bodies += 1;
    c.diameter = d_sum / c.bodies;
    c.mass = m_sum / c.bodies;
  }
  if (static_cast<int>(classes.size()) > max_classes)
    throw InvalidInput(where + ": contact.stiffness_scaling: \"linear\" needs " +
                       std::to_string(classes.size()) + " size classes (diameters within " +
                       format_number(100 * tolerance) + " % of each other), over the " +
                       std::to_string(max_classes) + " atom types the deck writes");
  return classes;
}

int stiffness_class_of(const std::vector<StiffnessClass>& classes, const SpecimenBody& body) {
  const double d = soil_diameter(body);
  for (std::size_t k = 0; k < classes.size(); ++k)
    if (d >= classes[k].d_min && d <= classes[k].d_max) return static_cast<int>(k);
  throw InvalidInput("LAMMPS export: body " + std::to_string(body.id) + " of diameter " +
                     format_number(d) + " m is in no stiffness class");
}

double stiffness_class_error(const std::vector<StiffnessClass>& classes) {
  double e = 0;
  for (const StiffnessClass& c : classes)
    e = std::max({e, std::abs(c.diameter / c.d_min - 1), std::abs(c.diameter / c.d_max - 1)});
  return e;
}

std::string lammps_class_pair_coeffs(const std::vector<StiffnessClass>& classes, int first_type,
                                     const dem::ContactParams& p) {
  std::string s;
  for (std::size_t i = 0; i < classes.size(); ++i)
    for (std::size_t j = i; j < classes.size(); ++j) {
      const StiffnessClass &a = classes[i], &b = classes[j];
      const double f = dem::pair_stiffness_factor(p, a.diameter, b.diameter);
      const double m_eff = a.mass * b.mass / (a.mass + b.mass);
      s += "pair_coeff  " + std::to_string(first_type + i) + " " + std::to_string(first_type + j) +
           " hooke " + format_number(p.kn * f) + " " +
           format_number(lammps_dashpot(p.kn * f, m_eff, p.damping_ratio)) +
           " tangential linear_history " + format_number(p.ks * f) + " 0 " +
           format_number(p.friction) + " damping mass_velocity\n";
    }
  return s;
}

std::string lammps_class_wall_law(const StiffnessClass& c, const dem::ContactParams& p, double mu,
                                  bool damped) {
  const double f = dem::wall_stiffness_factor(p, c.diameter);
  return "granular hooke " + format_number(p.kn * f) + " " +
         format_number(damped ? lammps_dashpot(p.kn * f, c.mass, p.damping_ratio) : 0.0) +
         " tangential linear_history " + format_number(p.ks * f) + " 0 " + format_number(mu) +
         " damping mass_velocity";
}

}  // namespace clumpkit
