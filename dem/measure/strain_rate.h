// Axial strain rate of the inside of an assembly from its bodies' velocities, away from the
// platens that bound it.
#pragma once

#include "dem/core/world.h"

namespace clumpkit::dem {

/// Rate of axial shortening (1/s, compression positive) of the bodies whose centroid lies in
/// z_lo <= z <= z_hi: minus the least-squares slope dv_z/dz of their vertical velocities
/// against their heights, the affine part of the velocity field. Integrated over the steps, it
/// is the strain an on-sample gauge would read: a platen's boundary layer (looser, sliding on
/// the flat wall, thicker the larger the particles) adds compliance to the strain from the
/// platens' distance that the bodies between the gauge planes do not feel. 0 for fewer than two
/// bodies in the band or all at one height. A sum in body order (deterministic).
double interior_axial_strain_rate(const World& world, double z_lo, double z_hi);

}  // namespace clumpkit::dem
