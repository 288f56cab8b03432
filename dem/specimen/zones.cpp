#include "dem/specimen/zones.h"

#include "geom/errors.h"
#include "geom/format.h"

#include <algorithm>
#include <cmath>

namespace clumpkit::dem {

double zone_coordinate(const ZoneLayout& layout, const Vec3& x) {
  switch (layout.coordinate) {
    case ZoneCoordinate::radial:
      return std::hypot(x.x() - layout.origin.x(), x.y() - layout.origin.y());
    case ZoneCoordinate::depth:
      return layout.origin.z() - x.z();
    case ZoneCoordinate::spherical:
      return (x - layout.origin).norm();
  }
  return 0.0;
}

int region_of(const ZoneLayout& layout, double c) {
  const int n = static_cast<int>(layout.regions.size());
  for (int k = 0; k < n; ++k)
    if (c < layout.regions[k].outer) return k;
  return n - 1;
}

bool mis_zoned(double d, double beyond, double placed_largest, double lo, double hi) {
  const double slack = 1e-9 * d;  // the same size drawn at the same scale, rounded
  const bool foreign = d < lo - slack || d > hi + slack;
  return foreign && beyond > std::max({d, placed_largest, hi});
}

double inner_bound(const ZoneLayout& layout, int k) {
  return k > 0 ? layout.regions.at(k - 1).outer : 0.0;
}

double small_scale(const ZoneLayout& layout, int k) {
  return std::min(layout.regions.at(k - 1).scale, layout.regions.at(k + 1).scale);
}

double large_scale(const ZoneLayout& layout, int k) {
  return std::max(layout.regions.at(k - 1).scale, layout.regions.at(k + 1).scale);
}

double small_fraction_at(const ZoneLayout& layout, int k, double c) {
  const ZoneRegion& r = layout.regions.at(k);
  const double inner = inner_bound(layout, k);
  const double t = std::clamp((c - inner) / (r.outer - inner), 0.0, 1.0);
  return r.small_fraction + t * (r.small_fraction_outer - r.small_fraction);
}

std::vector<std::string> validate_zones(const ZoneLayout& layout, double core_diameter) {
  const std::vector<ZoneRegion>& z = layout.regions;
  const int n = static_cast<int>(z.size());
  auto name = [](int k) { return "zones: region " + std::to_string(k + 1); };
  if (n == 0) throw InvalidInput("zones: no region");
  if (z.front().mixed || z.back().mixed)
    throw InvalidInput("zones: the first and the last region must be uniform zones");
  if (z.front().scale != 1.0)
    throw InvalidInput(name(0) + ": the core's scale must be 1 (the gradation as given), got " +
                       format_number(z.front().scale));
  std::vector<std::string> warnings;
  double inner = 0.0;
  for (int k = 0; k < n; ++k) {
    const ZoneRegion& r = z[k];
    require(kZoneOuter, r.outer, name(k) + ": outer bound");
    if (!(r.outer > inner))
      throw InvalidInput(name(k) + ": outer bound " + format_number(r.outer) +
                         " m must exceed the region before's (" + format_number(inner) +
                         " m): zones overlap");
    if (r.mixed) {
      if (z[k - 1].mixed || z[k + 1].mixed)
        throw InvalidInput(name(k) + ": two mixed layers side by side");
      for (const double f : {r.small_fraction, r.small_fraction_outer})
        if (!(f >= 0.0 && f <= 1.0))
          throw InvalidInput(name(k) + ": small_volume_fraction must be in [0, 1], got " +
                             format_number(f));
      const double large = large_scale(layout, k) * core_diameter;
      if (r.outer - inner < 2.0 * large)
        throw InvalidInput(name(k) + ": a mixed layer " + format_number(r.outer - inner) +
                           " m wide is narrower than two of its large particles (" +
                           format_number(2.0 * large) + " m)");
    } else {
      require(kZoneScale, r.scale, name(k) + ": scale");
      // The previous uniform zone (across a mixed layer).
      const int before = k >= 2 && z[k - 1].mixed ? k - 2 : k - 1;
      if (before >= 0) {
        const double ratio = std::max(r.scale / z[before].scale, z[before].scale / r.scale);
        if (ratio > 3.0)
          throw InvalidInput(name(k) + ": scale " + format_number(r.scale) + " next to " +
                             format_number(z[before].scale) +
                             ": neighbouring zones' sizes may differ 3 times at most (small "
                             "particles pass through the throats of dense large ones)");
        if (ratio > 2.0)
          warnings.push_back(name(k) + ": neighbouring zones' sizes differ " +
                             format_number(ratio, 3) +
                             " times (above 2: small particles may migrate into the large ones)");
      }
    }
    inner = r.outer;
  }
  return warnings;
}

}  // namespace clumpkit::dem
