// Similarity copy of a DEM world at length scale λ (CTGU 2017 eqs. 1–3).
#pragma once

#include "dem/core/world.h"

namespace clumpkit::dem {

/// The world λ times larger, in which every trajectory is the original one on the time axis
/// t → λt: lengths x → λx (about the origin), r → λr, diameters → λd; masses → λ³m, volumes → λ³V,
/// moments → λ⁵I; velocities unchanged, ω → ω/λ; forces → λ²F (contact normal and shear forces,
/// body forces), torques → λ³T, overlaps and contact points → λ; walls' points and radii → λ,
/// their speeds unchanged; time step, skin, clock → λ; gravity → g/λ; kn and ks → λ·k unless
/// linear stiffness scaling already scales them through the diameters (kn_ref and d_ref kept);
/// the corner stiffness of polyhedral bodies → λ·k, their corners → λ.
/// Friction and damping ratios are dimensionless and kept. For λ a power of two every product is
/// exact, so the copy's run equals the original's bit for bit (positions / λ, stresses).
/// Throws InvalidInput for λ not positive and finite, or a world with bonds (the cohesive law's
/// strengths and fracture energies set lengths of their own: no similar copy).
World scaled_world(const World& world, double lambda);

}  // namespace clumpkit::dem
