#include "io/export/lammps_deck.h"

#include "geom/format.h"

#include <cmath>

namespace clumpkit {

std::string lammps_run_command(int ranks) {
  return ranks <= 1
             ? "lmp -in in.clumpkit"
             : "mpirun --allow-run-as-root -np " + std::to_string(ranks) + " lmp -in in.clumpkit";
}

double lammps_atom_density(const SpecimenBody& body) {
  double spheres_volume = 0;
  for (const Sphere& s : body.spheres) spheres_volume += 4.0 / 3.0 * M_PI * std::pow(s.radius, 3);
  return body.mass / spheres_volume;
}

LammpsContact lammps_contact(const SpecimenExtents& e, const EngineSettings& settings) {
  // Contact law: kn, kt = ks, μ; the dashpot c = 2β·sqrt(m_eff·kn) becomes LAMMPS's
  // γn = c/m_eff at the median body's m_eff = m/2 (LAMMPS scales the dashpot with each pair's
  // m_eff, clumpkit with sqrt(m_eff)); no tangential dashpot (γt = 0), no local damping.
  const dem::ContactParams& c = settings.contact;
  const double m_eff = 0.5 * e.m_median;
  LammpsContact lc;
  lc.dt = 0.2 * std::sqrt(e.m_min / c.kn);  // 1/10 of the sphere's 2·sqrt(m/k)
  lc.skin = 0.5 * e.r_min;
  lc.cutoff = 2 * e.reach + 2 * e.r_max + 2 * lc.skin;
  lc.kn = c.kn;
  lc.kt = c.ks;
  lc.gamma_n = lammps_dashpot(c.kn, m_eff, c.damping_ratio);
  lc.wall_gamma_n = lammps_dashpot(c.kn, e.m_median, c.damping_ratio);
  lc.friction = c.friction;
  return lc;
}

std::string lammps_contact_args(const LammpsContact& contact, double mu) {
  return lammps_hooke_args(contact.kn, contact.kt, contact.gamma_n, mu);
}

std::string lammps_contact_args(const LammpsContact& contact) {
  return lammps_contact_args(contact, contact.friction);
}

std::string lammps_preamble(const LammpsContact& contact) {
  return "units       si\n"
         "atom_style  hybrid sphere molecular\n"
         "atom_modify map array\n"
         "boundary    f f f\n"
         "newton      off\n"
         "comm_modify vel yes cutoff " +
         format_number(contact.cutoff) + "\n";
}

}  // namespace clumpkit
