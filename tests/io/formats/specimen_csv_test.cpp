// specimen.csv round trips every body field, the zone column included; format 3 files (no zone
// column) still read; a bad zone is refused naming the file, line and field.
#include "io/formats/specimen_csv.h"

#include "dem/core/body.h"
#include "geom/errors.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace clumpkit {
namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::path(::testing::TempDir()) / ("clumpkit_spcsv_" + name)).string();
}

dem::World two_bodies() {
  dem::World world;
  dem::Body a = dem::make_sphere_body(Vec3(0.01, 0.02, 0.03), 0.004, 2650);
  a.zone = 2;
  dem::Body b = dem::make_sphere_body(Vec3(-0.01, 0.0, 0.05), 0.006, 2650);
  world.add_body(std::move(a));
  world.add_body(std::move(b));
  return world;
}

TEST(SpecimenCsv, RoundTripKeepsZones) {
  const std::string path = temp_path("zones.csv");
  write_specimen_csv(path, specimen_bodies(two_bodies()));
  const std::vector<SpecimenBody> read = read_specimen_csv(path);
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].zone, 2);
  EXPECT_EQ(read[1].zone, 0);
  EXPECT_EQ(dem_body(read[0]).zone, 2);
  EXPECT_EQ(read[1].position, Vec3(-0.01, 0.0, 0.05));
  EXPECT_EQ(read[1].spheres.at(0).radius, 0.006);
  std::filesystem::remove(path);
}

// The same file written as format 3 did: the header line and no zone field.
TEST(SpecimenCsv, FormatThreeReadsWithEveryBodyInZoneZero) {
  const std::string path = temp_path("v3.csv");
  {
    std::ofstream o(path);
    o << "# clumpkit specimen format 3, SI units\n# bodies\n"
         "body,kind,template,x,y,z,qw,qx,qy,qz,mass,volume,scale,I1,I2,I3\n"
         "1,soil,-1,0,0,0.01,1,0,0,0,0.001,3.7e-7,1,1e-9,1e-9,1e-9\n"
         "# spheres\nsphere,body,x,y,z,r\n1,1,0,0,0.01,0.0045\n";
  }
  const std::vector<SpecimenBody> read = read_specimen_csv(path);
  ASSERT_EQ(read.size(), 1u);
  EXPECT_EQ(read[0].zone, 0);
  std::filesystem::remove(path);
}

TEST(SpecimenCsv, BadZoneIsRefusedNamingFileLineAndField) {
  const std::string path = temp_path("badzone.csv");
  write_specimen_csv(path, specimen_bodies(two_bodies()));
  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::size_t row = text.find("\n1,soil,");
  ASSERT_NE(row, std::string::npos);
  const std::size_t end = text.find('\n', row + 1);
  text.replace(end - 2, 2, ",-3");  // the zone field "2" of body 1 becomes -3
  {
    std::ofstream o(path);
    o << text;
  }
  try {
    read_specimen_csv(path);
    ADD_FAILURE() << "a negative zone was accepted";
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path + ":5:"), std::string::npos) << what;
    EXPECT_NE(what.find("field zone"), std::string::npos) << what;
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace clumpkit
