// Variable particle-size zones (CTGU 2017): regions of a specimen, by distance to an axis, depth
// or distance to a point, each with the core gradation scaled by its size factor λ, or a mixed
// layer holding both neighbours' particles.
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/range.h"

#include <string>
#include <vector>

namespace clumpkit::dem {

/// What a zone's bounds measure.
enum class ZoneCoordinate {
  radial,    ///< distance from the vertical axis through `origin` (a CPT chamber, a pile)
  depth,     ///< origin.z − z: depth below the surface at origin.z (layers)
  spherical  ///< distance from `origin` (a cavity, a pile tip)
};

/// A region's outer bound (m; finite; above the previous region's too, as validate_zones checks)
/// and a uniform zone's size factor λ (finite).
inline constexpr Range kZoneOuter = above(0);
inline constexpr Range kZoneScale = above(0);

/// One region of the layout, from the previous region's outer bound (0 for the first) to
/// `outer` (m). Uniform: the core gradation × `scale`. Mixed: the particles of both neighbouring
/// zones, the smaller ones making `small_fraction` of the solid volume at the inner bound and
/// `small_fraction_outer` at the outer one (linear between; equal for a constant fraction).
struct ZoneRegion {
  bool mixed = false;
  double outer = 0.0;                 ///< in kZoneOuter
  double scale = 1.0;                 ///< uniform only: λ, in kZoneScale
  double small_fraction = 0.5;        ///< mixed only
  double small_fraction_outer = 0.5;  ///< mixed only
};

/// The zones of a specimen, innermost first: uniform zones, with at most one mixed layer
/// between two of them; the first and the last are uniform, the first has λ = 1 (the core).
struct ZoneLayout {
  ZoneCoordinate coordinate = ZoneCoordinate::radial;
  Vec3 origin = Vec3::Zero();
  std::vector<ZoneRegion> regions;
};

/// The layout's coordinate of the point x (m).
double zone_coordinate(const ZoneLayout& layout, const Vec3& x);

/// Region k's inner bound: the previous region's outer one, 0 for the first.
double inner_bound(const ZoneLayout& layout, int k);

/// The region holding coordinate c: the first whose outer bound exceeds c, the last one for c
/// beyond every bound.
int region_of(const ZoneLayout& layout, double c);

/// A mixed region's small and large size factors: the smaller and the larger λ of the uniform
/// regions on either side.
double small_scale(const ZoneLayout& layout, int mixed_region);
double large_scale(const ZoneLayout& layout, int mixed_region);

/// The volume fraction of small particles at coordinate c inside mixed region k.
double small_fraction_at(const ZoneLayout& layout, int mixed_region, double c);

/// Whether a body of diameter d that ended `beyond` (m) outside the zone it was placed in, whose
/// largest drawn diameter is `placed_largest`, is out of place in the zone it ended in, drawn
/// with diameters [lo, hi]: its size is not one of that zone's, and it went further than the
/// largest diameter of either zone. A bound between two zones is rough on the scale of their
/// largest particles (the first layer of large ones leaves pockets about one diameter deep that
/// the small ones of the neighbour fill), and a small sphere of a mixed layer in a core of the
/// same spheres is where its size belongs. Sizes equal to 1e-9 relative count as the same.
bool mis_zoned(double d, double beyond, double placed_largest, double lo, double hi);

/// Throws InvalidInput, naming the region, for a layout CTGU 2017's method cannot build: no
/// region, a bound outside kZoneOuter or not above the one before, a first region that is not a
/// uniform λ = 1 core, a mixed region first, last or next to another, a small fraction outside
/// [0, 1], a λ outside kZoneScale, neighbouring λ in a ratio above 3 (small particles pass the
/// throats of dense large ones), or a mixed layer narrower than two of its large particles
/// (`core_diameter` × the large λ: the largest core particle). Returns the warnings: λ ratios
/// above 2.
std::vector<std::string> validate_zones(const ZoneLayout& layout, double core_diameter);

}  // namespace clumpkit::dem
