// Contact stiffness ∝ diameter (CTGU 2017's groups D–E) in LAMMPS: size classes as atom types,
// each pair of types and each wall its own Hookean coefficients.
#pragma once

#include "dem/core/contact.h"
#include "io/formats/specimen_csv.h"

#include <string>
#include <vector>

namespace clumpkit {

/// LAMMPS's normal dashpot γn = 2β·sqrt(kn/m_eff): clumpkit's c = 2β·sqrt(m_eff·kn) over m_eff,
/// as LAMMPS multiplies its coefficient by each contact's m_eff (a wall's m_eff is the body's m).
double lammps_dashpot(double kn, double m_eff, double beta);

/// The arguments of gran/hooke/history (pairs and walls): "kn kt γn 0 μ 1" (no tangential
/// dashpot, friction limited).
std::string lammps_hooke_args(double kn, double kt, double gamma_n, double mu);

/// Spheres of one size: LAMMPS's granular styles take a stiffness per pair of atom types, not
/// per atom, so linear scaling becomes one type per class (the class's mean diameter) of
/// soil spheres whose diameters lie within the class's tolerance.
struct StiffnessClass {
  double diameter = 0;          ///< mean (m): the d of dem::pair_stiffness_factor
  double mass = 0;              ///< mean body mass (kg): the class's m_eff in the dashpots
  double d_min = 0, d_max = 0;  ///< the diameters it holds (m)
  std::size_t bodies = 0;
};

/// The classes of soil spheres' diameters, smallest first: a class ends at the first diameter
/// more than `tolerance` (relative) above its smallest. The stiffness a class gives a sphere is
/// then off by at most `tolerance` (stiffness_class_error). Throws InvalidInput, naming `where`,
/// for a rock body (a clump's d is its own; one type each is not what LAMMPS's pair tables are
/// for) and for more than `max_classes` classes.
std::vector<StiffnessClass> stiffness_classes(const std::vector<SpecimenBody>& bodies,
                                              const std::string& where, double tolerance = 0.05,
                                              int max_classes = 16);

/// The class of a soil body (index into `classes`): the one whose diameters hold its d.
int stiffness_class_of(const std::vector<StiffnessClass>& classes, const SpecimenBody& body);

/// Largest relative error of the stiffness any sphere gets from its class's mean diameter
/// instead of its own (against a wall: |d_class/d − 1|).
double stiffness_class_error(const std::vector<StiffnessClass>& classes);

/// pair_coeff of the classes' types (class k is atom type first_type + k) for pair_style
/// granular: hooke kn_ij γ_ij, linear_history kt_ij 0 μ, damping mass_velocity, with kn_ij, kt_ij
/// of dem::pair_stiffness_factor and γ_ij = 2β·sqrt(kn_ij/m_eff) at the classes' masses (the
/// critical-ratio dashpot of clumpkit's contact, which LAMMPS multiplies by each pair's m_eff).
std::string lammps_class_pair_coeffs(const std::vector<StiffnessClass>& classes, int first_type,
                                     const dem::ContactParams& contact);

/// A wall's law for class k in fix wall/gran/region's granular syntax: "granular hooke kn γ
/// tangential linear_history kt 0 μ damping mass_velocity" with dem::wall_stiffness_factor;
/// γ = 2β·sqrt(kn/m) when `damped` (m the class's mass, a wall's m_eff), else 0.
std::string lammps_class_wall_law(const StiffnessClass& c, const dem::ContactParams& contact,
                                  double mu, bool damped);

}  // namespace clumpkit
