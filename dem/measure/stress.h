// Stress of a granular assembly: wall forces and the Love–Weber average over a region.
#pragma once

#include "dem/core/world.h"

#include <functional>

namespace clumpkit::dem {

/// Force the bodies exert on wall `wall` (N): minus the sum of the forces of its contacts
/// (WallContact::state.force() acts on the sphere), in contact order, then of the corners of
/// polyhedral bodies on it (VertexContact).
Vec3 wall_force(const World& world, int wall);

/// Forces the spheres exert on a probe wall (N), apart by the part each contact touches: the
/// part of the one closest profile point (wall_hit) at the spheres' present positions, so no
/// contact is counted on both the tip and the sleeve. Throws InvalidInput for a wall that is
/// not a probe.
struct ProbeForces {
  Vec3 tip = Vec3::Zero();
  Vec3 sleeve = Vec3::Zero();
};
ProbeForces probe_forces(const World& world, int wall);

/// Normal stress on a plane wall of area `area` (Pa, compression positive): the push of the
/// spheres against its normal, −wall_force·n / A. For a cylinder, the mean radial pressure over
/// its area `area` (2πR·h for a height h): Σ over contacts of the outward radial push, / A.
double wall_stress(const World& world, int wall, double area);

/// Sum of the normal stiffnesses of the wall's touching contacts (N/m), size scaling included,
/// plus each contact's dashpot over the time step, c/dt: the force one step of wall motion
/// adds (k·v·dt from the spring, c·v from the dashpot), which a servo gain must divide by — a
/// gain on the springs alone makes a viscously damped packing chatter.
double wall_contact_stiffness(const World& world, int wall);

/// Love–Weber average stress (Pa, compression positive, symmetrised):
/// σ = −(1/V) Σ_b Σ_c sym((x_c − x_b) ⊗ f_c) over the bodies b whose centroid x_b satisfies
/// `inside`, for every contact c of b (pairs and walls) at point x_c with force f_c on b. For a
/// body in equilibrium this is Σ_c f ⊗ l over its contacts' branch vectors (Love 1927;
/// Weber 1966; Christoffersen et al. 1981). V the region's volume (m³).
Mat3 love_weber_stress(const World& world, const std::function<bool(const Vec3&)>& inside,
                       double volume);

/// Mean and deviatoric invariants of a stress (compression positive): p = tr σ / 3 and
/// q = sqrt(3/2 s:s) with s = σ − p·I (for axisymmetric σ1 > σ2 = σ3, q = σ1 − σ3).
double mean_stress(const Mat3& s);
double deviator_stress(const Mat3& s);

/// Coordination number Z = 2·C/N: C the body pairs touching through at least one sphere pair
/// (a clump touching another at two spheres is one contact), N all bodies (rattlers included).
double coordination_number(const World& world);

}  // namespace clumpkit::dem
