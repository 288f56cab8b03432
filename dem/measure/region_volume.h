// Solid volume and porosity of a DEM assembly inside a vertical cylindrical region, from exact
// sphere-region volumes (clump overlaps counted once), the column height and the coordination
// number.
#pragma once

#include "dem/core/world.h"

#include <array>
#include <vector>

namespace clumpkit::dem {

/// The region r < radius around the z-axis, z_lo <= z <= z_hi (m).
struct CylinderRegion {
  double radius = 0.0;
  double z_lo = 0.0, z_hi = 0.0;
  double volume() const;
};

/// Exact volume (m³) of the union of each body's spheres: Body::volume (scaled from the body's
/// template, or 4/3·π·r³ for a soil sphere). Throws InvalidInput for a body without a positive
/// volume.
std::vector<double> body_volumes(const World& world);

/// Height of a uniform column with the same volume-weighted mean height as the bodies:
/// H = 2·z̄ (a level top surface at H puts the mean at H/2); 0 without bodies.
double column_height(const World& world);

/// Volume of (union of the body's spheres) ∩ region. A body wholly inside counts its exact
/// volume, one wholly outside nothing; a body cut by the region's boundary is integrated over z
/// of the exact area of (union of its slice disks) ∩ (region disk), the latter from
/// union_of_disks by inclusion–exclusion A(U ∩ D) = A(U) + A(D) − A(U ∪ D), by adaptive Simpson
/// quadrature to 1e-9 of the body volume (the slice area is continuous with isolated kinks).
double body_region_volume(const Body& body, double body_volume, const CylinderRegion& region);

/// body_region_volume for the regions of radius `radius` between each z range's planes (in any
/// order, overlapping or not), into `out` (one per range): the body's height cut at those
/// planes, each piece integrated once however many ranges hold it. A single sphere takes closed
/// forms: the cap integral between the planes, the lens of its slice and the region's disk.
void body_region_volumes(const Body& body, double body_volume, double radius,
                         const std::vector<std::array<double, 2>>& z_ranges,
                         std::vector<double>& out);

/// region_porosity of several regions of one radius (the layers and bands of a specimen's
/// profile), each body integrated once. Throws InvalidInput for an empty region or radii that
/// differ.
std::vector<double> region_porosities(const World& world, const std::vector<double>& volumes,
                                      const std::vector<CylinderRegion>& regions);

/// Porosity of the region: 1 − Σ body_region_volume / region volume. Overlaps inside a clump
/// count once; the contact overlaps between bodies (≈ mg/kn, nanometres here) count twice and
/// are negligible. Throws InvalidInput for an empty region or mismatched volumes.
double region_porosity(const World& world, const std::vector<double>& volumes,
                       const CylinderRegion& region);

/// Mean coordination number of the bodies whose centroid lies in the region: the number of
/// distinct other bodies each touches (several sphere contacts between two clumps count once;
/// walls excluded). 0 when no body lies in the region.
double coordination_number(const World& world, const CylinderRegion& region);

}  // namespace clumpkit::dem
