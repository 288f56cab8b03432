// Tests of element-test recipes (io/recipes/lab_recipe.h): the bundled ones parse to their values,
// bad ones fail with the file, field and value in one line.
#include "io/recipes/lab_recipe.h"

#include "../../invalid_input_message.h"
#include "geom/errors.h"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

using namespace clumpkit;

namespace {

std::string test_error_of(const std::string& text) {
  return invalid_input_message([&] { parse_test_recipe(text, "t.toml"); });
}

}  // namespace

// CTGU 2017's Table 1 law.
TEST(TestRecipe, BundledTable1RecipeGivesTheCtgu2017Law) {
  const TestRecipe r = read_test_recipe(std::string(CLUMPKIT_SOURCE_DIR) +
                                        "/assets/recipes/elastic-scaling-table1.toml");
  EXPECT_EQ(r.settings.confining, 5e6);
  EXPECT_EQ(r.settings.friction, 0.8);
  EXPECT_EQ(r.settings.consolidation_friction, 0.8);
  EXPECT_EQ(r.settings.servo_strain_rate, 2.7);
  EXPECT_EQ(r.settings.max_axial_strain, 3e-4);
  ASSERT_TRUE(r.scaling && r.kn_ref && r.d_ref && r.ks_over_kn);
  EXPECT_EQ(*r.scaling, dem::StiffnessScaling::linear);
  EXPECT_EQ(*r.kn_ref, 8e7);
  EXPECT_EQ(*r.d_ref, 0.01);
  EXPECT_EQ(*r.ks_over_kn, 0.01);
}

// The CPT of CTGU 2017's chamber: 300 kPa, an 18 mm 60° cone at 20 mm/s to 8 D_c.
TEST(TestRecipe, BundledCptRecipeGivesItsProbe) {
  const TestRecipe r =
      read_test_recipe(std::string(CLUMPKIT_SOURCE_DIR) + "/assets/recipes/test-cpt.toml");
  EXPECT_EQ(r.settings.confining, 300e3);
  EXPECT_EQ(r.settings.friction, 0.5);
  ASSERT_TRUE(r.probe.has_value());
  EXPECT_EQ(r.probe->diameter, 0.018);
  EXPECT_EQ(r.probe->apex_deg, 60.0);
  EXPECT_EQ(r.probe->velocity, 0.02);
  EXPECT_EQ(r.probe->depth, 8 * 0.018);
  EXPECT_LT(r.probe->friction, 0.0);  // the test's
  EXPECT_FALSE(parse_test_recipe("[test]\nconfining = 1e5\n", "t.toml").probe.has_value());
  const std::string e = test_error_of("[probe]\ndepth = 0.1\napex_deg = 200\n");
  EXPECT_NE(e.find("probe.apex_deg"), std::string::npos) << e;
  EXPECT_NE(e.find("200"), std::string::npos) << e;
  EXPECT_NE(test_error_of("[probe]\ndiameter = 0.01\n").find("probe.depth"), std::string::npos);
  EXPECT_NE(test_error_of("[probe]\ndepth = 0.1\nvelocity = -1\n").find("probe.velocity"),
            std::string::npos);
}

TEST(TestRecipe, DefaultsLeaveConsolidationAndServoToTheTest) {
  const TestRecipe r = parse_test_recipe("[test]\nconfining = 1e5\n", "t.toml");
  EXPECT_LT(r.settings.consolidation_friction, 0.0);  // the test's μ
  EXPECT_EQ(r.settings.servo_strain_rate, 0.0);       // the per-step default
  EXPECT_FALSE(r.scaling.has_value());
  EXPECT_EQ(r.density_scaling, 1.0);
  EXPECT_EQ(parse_test_recipe("[test]\ndensity_scaling = 25\n", "t.toml").density_scaling, 25.0);
}

TEST(TestRecipe, BadValuesNameFileFieldAndValue) {
  const std::string e1 = test_error_of("[test]\nconsolidation_friction = -0.1\n");
  EXPECT_NE(e1.find("t.toml"), std::string::npos) << e1;
  EXPECT_NE(e1.find("test.consolidation_friction"), std::string::npos) << e1;
  EXPECT_NE(e1.find("-0.1"), std::string::npos) << e1;
  const std::string e2 = test_error_of("[test]\nservo_strain_rate = -1\n");
  EXPECT_NE(e2.find("test.servo_strain_rate"), std::string::npos) << e2;
  const std::string e3 = test_error_of("[test]\nservo_rate = 1\n");
  EXPECT_NE(e3.find("unknown key"), std::string::npos) << e3;
  EXPECT_NE(e3.find("servo_strain_rate"), std::string::npos) << e3;  // the known keys listed
  for (const char* bad : {"0.5", "nan", "-2"}) {
    const std::string e = test_error_of(std::string("[test]\ndensity_scaling = ") + bad + "\n");
    EXPECT_NE(e.find("t.toml: test.density_scaling: "), std::string::npos) << e;
    EXPECT_NE(e.find(bad), std::string::npos) << e;
  }
}

TEST(TestRecipe, InertialNumberIsHeldOnlyWhenAskedAndQuasiStatic) {
  EXPECT_EQ(parse_test_recipe("[test]\nconfining = 1e5\n", "t.toml").settings.inertial_number, 0.0);
  EXPECT_EQ(
      parse_test_recipe("[test]\ninertial_number = 5e-3\n", "t.toml").settings.inertial_number,
      5e-3);
  for (const char* name : {"test-oedometer-rockfill", "test-triaxial-rockfill"}) {
    const TestRecipe r =
        read_test_recipe(std::string(CLUMPKIT_SOURCE_DIR) + "/assets/recipes/" + name + ".toml");
    EXPECT_EQ(r.settings.inertial_number, 1e-2) << name;
    EXPECT_EQ(r.density_scaling, 1000.0) << name;
  }
  // 0 is off and there is no bound above, as the engine takes it (dem::kHeldInertialNumber).
  EXPECT_EQ(parse_test_recipe("[test]\ninertial_number = 0\n", "t.toml").settings.inertial_number,
            0.0);
  for (const char* bad : {"-1e-3", "nan"}) {
    const std::string e = test_error_of(std::string("[test]\ninertial_number = ") + bad + "\n");
    EXPECT_NE(e.find("t.toml: test.inertial_number: "), std::string::npos) << e;
  }
}

TEST(TestRecipe, HoldStressesRiseFromTheConfiningToTheFinalStress) {
  const TestRecipe r = parse_test_recipe(
      "[test]\nconfining = 1e5\nfinal_stress = 1e6\nhold_stresses = [2e5, 5e5, 1e6]\n"
      "max_hold_steps = 5000\n",
      "t.toml");
  EXPECT_EQ(r.settings.hold_stresses, (std::vector<double>{2e5, 5e5, 1e6}));
  EXPECT_EQ(r.settings.max_hold_steps, 5000);
  EXPECT_TRUE(parse_test_recipe("[test]\n", "t.toml").settings.hold_stresses.empty());
  // The order of keys in the table does not matter: checked against both stresses at the end.
  EXPECT_EQ(parse_test_recipe("[test]\nhold_stresses = [3e5]\nconfining = 1e5\n", "t.toml")
                .settings.hold_stresses.size(),
            1u);
  const std::string base = "[test]\nconfining = 1e5\nfinal_stress = 1e6\n";
  for (const auto& [bad, field, shown] : std::vector<std::array<std::string, 3>>{
           {"hold_stresses = [5e5, 2e5]", "test.hold_stresses[1]", "200000"},
           {"hold_stresses = [1e5]", "test.hold_stresses[0]", "100000"},
           {"hold_stresses = [2e6]", "test.hold_stresses[0]", "2000000"},
           {"hold_stresses = []", "test.hold_stresses", "[]"},
           {"hold_stresses = [\"a\"]", "test.hold_stresses[0]", "a"},
           {"hold_stresses = 3e5", "test.hold_stresses", "300000"},
           {"max_hold_steps = 10", "test.max_hold_steps", "10"}}) {
    const std::string e = test_error_of(base + bad + "\n");
    EXPECT_NE(e.find("t.toml: " + field + ": "), std::string::npos) << e;
    EXPECT_NE(e.find(shown), std::string::npos) << e;
  }
}
