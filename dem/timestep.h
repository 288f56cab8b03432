// Critical time step of the linear spring contact law, used to choose a stable DEM step.
#pragma once

namespace clumpkit::dem {

/// Critical time step of a mass-spring oscillator, dt = sqrt(m / k) (the PFC convention for the
/// linear contact model; the undamped period is 2π·sqrt(m/k)). Mass in kg, stiffness in N/m.
/// Throws InvalidInput for non-positive or non-finite arguments.
double critical_timestep(double mass, double stiffness);

}  // namespace clumpkit::dem
