// bonds.csv round trips every bond and point to the bit (damage, slip and failure mix included),
// and refuses a bond to a body the specimen does not have, naming the file, line and field.
#include "io/formats/bonds_csv.h"

#include "dem/core/body.h"
#include "geom/errors.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace clumpkit {
namespace {

std::string bonds_temp_path(const std::string& name) {
  return (std::filesystem::path(::testing::TempDir()) / ("clumpkit_bonds_" + name)).string();
}

SpecimenBonds one_bond() {
  dem::Body a = dem::make_sphere_body(Vec3(0.0, 0.0, 0.0), 0.004, 2650);
  dem::Body b = dem::make_sphere_body(Vec3(0.007, 0.001, 0.0), 0.004, 2650);
  a.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
  SpecimenBonds s;
  s.law.sigma_n *= 1.85;
  s.bonds.push_back(dem::make_bond(a, b, 0, 1, Vec3(1, 0.1, 0).normalized(),
                                   {Vec3(0.0035, 0.0005, 0.001), Vec3(0.0035, 0.0, -0.001)},
                                   {1e-5, 2e-5}, 1.1));
  s.bonds[0].points[1].state.damage = 0.25;
  s.bonds[0].points[1].state.slip = Vec3(1e-6, -2e-6, 3e-7);
  s.bonds[0].points[0].state.damage = 1.0;
  s.bonds[0].points[0].state.failure_mix = 0.3;
  return s;
}

TEST(BondsCsv, RoundTripKeepsEveryBit) {
  const std::string path = bonds_temp_path("round.csv");
  const SpecimenBonds s = one_bond();
  write_bonds_csv(path, s);
  const SpecimenBonds r = read_bonds_csv(path, 2);
  EXPECT_EQ(r.law.sigma_n, s.law.sigma_n);
  EXPECT_EQ(r.law.g_t, s.law.g_t);
  ASSERT_EQ(r.bonds.size(), 1u);
  const dem::Bond &x = r.bonds[0], &y = s.bonds[0];
  EXPECT_EQ(x.a, 0);
  EXPECT_EQ(x.b, 1);
  EXPECT_EQ(x.normal_in_a, y.normal_in_a);
  EXPECT_EQ(x.factor, y.factor);
  ASSERT_EQ(x.points.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(x.points[k].in_a, y.points[k].in_a);
    EXPECT_EQ(x.points[k].in_b, y.points[k].in_b);
    EXPECT_EQ(x.points[k].area, y.points[k].area);
    EXPECT_EQ(x.points[k].state.damage, y.points[k].state.damage);
    EXPECT_EQ(x.points[k].state.slip, y.points[k].state.slip);
    EXPECT_EQ(x.points[k].state.failure_mix, y.points[k].state.failure_mix);
  }
  std::filesystem::remove(path);
}

TEST(BondsCsv, ABondToAMissingBodyIsRefusedNamingLineAndField) {
  const std::string path = bonds_temp_path("missing.csv");
  write_bonds_csv(path, one_bond());
  try {
    read_bonds_csv(path, 1);  // the specimen has one body: body 2 is not there
    FAIL() << "read a bond to a missing body";
  } catch (const InvalidInput& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(path + ":7:"), std::string::npos) << m;
    EXPECT_NE(m.find("field b"), std::string::npos) << m;
  }
  EXPECT_THROW(read_bonds_csv(bonds_temp_path("absent.csv"), 2), IoError);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace clumpkit
