// Critical time step of the linear spring contact law, used to choose a stable DEM step.
#pragma once

#include "dem/core/body.h"
#include "dem/core/world.h"
#include "geom/range.h"

namespace clumpkit::dem {

/// The safety factor on critical_timestep a run's time step takes (a deposition, a compression,
/// a crushing test, an element test): at 1 the step is sqrt(m/k), inside the explicit
/// integration's limit √2·sqrt(m/k) of the stiffest equal pair (ω² = 2·k/m).
inline constexpr Range kTimestepSafety = open_closed(0, 1);

/// Critical time step of a mass-spring oscillator, dt = sqrt(m / k) (the PFC convention for the
/// linear contact model; the undamped period is 2π·sqrt(m/k)). Mass in kg, stiffness in N/m.
/// Throws InvalidInput for non-positive or non-finite arguments.
double critical_timestep(double mass, double stiffness);

/// Critical time step of one rigid body (s): the smaller of sqrt(m / kn) and, for each principal
/// axis a, sqrt(I_a / (k·r_a²)) with k = max(kn, ks) and r_a the largest distance of the body's
/// surface from that axis (sphere centre distance + radius, or a corner of Body::vertices), the
/// lever arm a contact force can have about it. Tighter than using the bounding radius for every
/// axis, which overestimates the lever arm about the long axis of an elongated clump.
double body_critical_timestep(const Body& body, double kn, double ks);

/// Critical time step of a world (s): the minimum of body_critical_timestep over its bodies with
/// the stiffness of each body's contact with an equal body (kn; under linear scaling kn·d/d_ref,
/// so that both laws give the same margin on the fastest contact frequency, ω² = 2·k/m for an
/// equal pair or, under linear scaling, a wall; bodies added to the world, whose diameter is
/// set), plus the stiffness of each body's bonds (bond_stiffness, summed) and, for a polyhedral
/// body, two corner springs (vertex_stiffness); +∞ for a world without bodies.
/// The one time-step rule of clumpkit: multiply by a safety factor (0.2 for general use, 0.35
/// measured stable for the specimen's settling runs) for the step.
double critical_timestep(const World& world);

}  // namespace clumpkit::dem
