// Zone layouts (dem/specimen/zones.h): coordinates, regions, the mixed layer's fraction, and the
// guard rails of CTGU 2017's method.
#include "dem/specimen/zones.h"
#include "../../invalid_input_message.h"
#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

// CTGU 2017's group E: a 6 mm core to 75 mm, a mixed layer to 115 mm, 18 mm particles (λ 3) to
// the 150 mm wall.
ZoneLayout group_e() {
  ZoneLayout z;
  z.coordinate = ZoneCoordinate::radial;
  z.origin = Vec3(0.01, -0.02, 0.5);
  z.regions = {
      {false, 0.075, 1.0, 0.5, 0.5}, {true, 0.115, 1.0, 0.37, 0.37}, {false, 0.150, 3.0, 0.5, 0.5}};
  return z;
}

std::string error_of(const ZoneLayout& z, double d) {
  return invalid_input_message([&] { validate_zones(z, d); });
}

}  // namespace

TEST(Zones, CoordinatesAndRegions) {
  ZoneLayout z = group_e();
  EXPECT_NEAR(zone_coordinate(z, Vec3(0.01 + 0.03, -0.02 + 0.04, -7.0)), 0.05, 1e-15);
  EXPECT_EQ(region_of(z, 0.0), 0);
  EXPECT_EQ(region_of(z, 0.0749), 0);
  EXPECT_EQ(region_of(z, 0.075), 1);  // a bound belongs to the region outside it
  EXPECT_EQ(region_of(z, 0.12), 2);
  EXPECT_EQ(region_of(z, 0.5), 2);  // beyond the last bound: the last region
  EXPECT_EQ(small_scale(z, 1), 1.0);
  EXPECT_EQ(large_scale(z, 1), 3.0);
  EXPECT_EQ(small_fraction_at(z, 1, 0.09), 0.37);
  z.regions[1].small_fraction = 1.0;  // linear from all small at 75 mm to all large at 115 mm
  z.regions[1].small_fraction_outer = 0.0;
  EXPECT_NEAR(small_fraction_at(z, 1, 0.085), 0.75, 1e-12);
  EXPECT_EQ(small_fraction_at(z, 1, 0.2), 0.0);
  z.coordinate = ZoneCoordinate::depth;
  EXPECT_NEAR(zone_coordinate(z, Vec3(3, 4, 0.2)), 0.3, 1e-15);
  z.coordinate = ZoneCoordinate::spherical;
  EXPECT_NEAR(zone_coordinate(z, z.origin + Vec3(0.03, 0.0, 0.04)), 0.05, 1e-15);
  EXPECT_TRUE(validate_zones(group_e(), 0.006).size() == 1);  // λ 3: allowed, with a warning
}

TEST(Zones, MisZonedIsAForeignSizeBeyondTheBoundsRoughness) {
  // Group E: 6 mm core, 6 + 18 mm mixed layer, 18 mm outer zone (m).
  // A 6 mm sphere of the mixed layer 30 mm into the core: its size belongs there.
  EXPECT_FALSE(mis_zoned(0.006, 0.030, 0.018, 0.006, 0.006));
  // One 8 mm into the 18 mm zone sits in a pocket of its first layer; 20 mm in, it has migrated.
  EXPECT_FALSE(mis_zoned(0.006, 0.008, 0.018, 0.018, 0.018));
  EXPECT_TRUE(mis_zoned(0.006, 0.020, 0.018, 0.018, 0.018));
  // An 18 mm sphere of the mixed layer 19 mm into the 6 mm core.
  EXPECT_TRUE(mis_zoned(0.018, 0.019, 0.018, 0.006, 0.006));
  EXPECT_FALSE(mis_zoned(0.018, 0.017, 0.018, 0.006, 0.006));
  // Between a 5 mm core and 10 mm spheres: the roughness is the larger diameter, either way.
  EXPECT_FALSE(mis_zoned(0.005, 0.009, 0.005, 0.0099, 0.0101));
  EXPECT_TRUE(mis_zoned(0.005, 0.011, 0.005, 0.0099, 0.0101));
  EXPECT_TRUE(mis_zoned(0.010, 0.011, 0.0101, 0.00495, 0.00505));
  // The same size drawn at the same scale, rounded, is not foreign.
  EXPECT_FALSE(mis_zoned(0.006 * (1 + 1e-12), 0.5, 0.018, 0.006, 0.006));
}

TEST(Zones, GuardRailsRefuseWhatTheMethodCannotBuild) {
  const double d = 0.006;
  ZoneLayout z = group_e();
  z.regions[2].outer = 0.1;  // overlaps the mixed layer
  EXPECT_NE(error_of(z, d).find("zones overlap"), std::string::npos) << error_of(z, d);
  z = group_e();
  z.regions[2].scale = 3.2;
  EXPECT_NE(error_of(z, d).find("3 times at most"), std::string::npos) << error_of(z, d);
  z = group_e();
  z.regions[1].outer = 0.08;  // 5 mm < two 18 mm particles
  EXPECT_NE(error_of(z, d).find("narrower than two of its large particles"), std::string::npos)
      << error_of(z, d);
  z = group_e();
  z.regions[0].scale = 2.0;
  EXPECT_NE(error_of(z, d).find("core's scale must be 1"), std::string::npos);
  z = group_e();
  z.regions[1].small_fraction = 1.5;
  EXPECT_NE(error_of(z, d).find("small_volume_fraction"), std::string::npos);
  z = group_e();
  z.regions.pop_back();  // a mixed layer last
  EXPECT_NE(error_of(z, d).find("first and the last"), std::string::npos);
  z = group_e();
  z.regions.insert(z.regions.begin() + 1, ZoneRegion{true, 0.07, 1.0, 0.5, 0.5});
  z.regions[0].outer = 0.03;
  EXPECT_NE(error_of(z, d).find("two mixed layers"), std::string::npos) << error_of(z, d);
  EXPECT_NE(error_of(ZoneLayout{}, d).find("no region"), std::string::npos);
  // λ 2 next to the core, no mixed layer: no warning.
  z = group_e();
  z.regions.erase(z.regions.begin() + 1);
  z.regions[1].scale = 2.0;
  EXPECT_TRUE(validate_zones(z, d).empty());
}
