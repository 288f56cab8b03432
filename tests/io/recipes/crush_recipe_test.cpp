// Crushing recipes: the bundled ones parse to the paper's sets, the calibration factor scales
// strengths and energies, and bad values name file, field and value.
#include "io/recipes/crush_recipe.h"

#include "../../invalid_input_message.h"
#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace clumpkit;

namespace {

std::string recipe(const char* name) {
  return std::string(CLUMPKIT_SOURCE_DIR) + "/assets/recipes/" + name;
}

std::string error_of(const std::string& text) {
  return invalid_input_message([&] { parse_crush_recipe(text, "r.toml"); });
}

}  // namespace

TEST(CrushRecipe, BundledRecipesHoldThePapersSets) {
  const CrushRecipe t1 = read_crush_recipe(recipe("crush-table1.toml"));
  ASSERT_EQ(t1.sets.size(), 5u);
  const double sizes[] = {0.0275, 0.0316, 0.0357, 0.0397, 0.0439};
  const int cells[] = {75, 114, 165, 229, 307};  // Hu et al. 2023 Table 1
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(t1.sets[k].polyhedron.diameter, sizes[k]);
    EXPECT_EQ(t1.sets[k].samples, 30);
    EXPECT_EQ(t1.sets[k].polyhedron.planes, 30);
    EXPECT_NEAR(std::pow(sizes[k] / t1.cells.cell_size, 3), cells[k], 1.5);
  }
  // The paper's law as read, times the Brazilian calibration s (σ × s, G × s²).
  EXPECT_EQ(t1.scale, 1.85);
  EXPECT_DOUBLE_EQ(t1.law.sigma_n, 9e6 * 1.85);
  EXPECT_DOUBLE_EQ(t1.law.g_n, 900.0 * 1.85 * 1.85);
  EXPECT_EQ(t1.law.friction, 0.3);
  EXPECT_EQ(t1.rig.strain_rate, 0.4);
  EXPECT_EQ(t1.rig.platen_friction, 0.3);
  EXPECT_EQ(t1.strength.min, 0.75);
  EXPECT_EQ(t1.strength.max, 1.25);

  const CrushRecipe t2 = read_crush_recipe(recipe("crush-table2.toml"));
  ASSERT_EQ(t2.sets.size(), 7u);
  EXPECT_EQ(t2.sets[0].name, "S1");
  EXPECT_NEAR(t2.sets[6].polyhedron.E, 2.0 / 3.0, 1e-4);  // S3: L:I:S = 1 : 2/3 : 4/9
  EXPECT_NEAR(t2.sets[6].polyhedron.F, 2.0 / 3.0, 1e-4);
  EXPECT_EQ(t2.sets[4].axis, 0);  // S3 long
  EXPECT_EQ(t2.sets[6].axis, 2);  // S3 short
  for (const CrushSet& s : t2.sets) EXPECT_FALSE(s.size_law);
  EXPECT_EQ(t2.rig.bed_depth, 0.15);  // the seat: the lowest cells bedded
  EXPECT_EQ(t1.rig.bed_depth, 0.0);   // Table 1's particles rest on a face

  const CrushRecipe b = read_crush_recipe(recipe("crush-brazilian.toml"));
  ASSERT_EQ(b.sets.size(), 1u);
  EXPECT_EQ(b.sets[0].shape, "cylinder");
  EXPECT_EQ(b.sets[0].axis, 0);
  const double d_eq = std::cbrt(1.5 * 0.05 * 0.05 * 0.05);
  EXPECT_NEAR(std::pow(d_eq / b.cells.cell_size, 3), 800, 5);  // the paper's ~800 cells
}

TEST(CrushRecipe, OneFactorScalesStrengthsAndTheOpeningsWithThem) {
  const CrushRecipe r =
      parse_crush_recipe("[bond]\nscale = 1.5\n[[set]]\nname = \"a\"\ndiameter = 0.02\n", "r.toml");
  EXPECT_DOUBLE_EQ(r.law.sigma_n, 1.5 * 9e6);
  EXPECT_DOUBLE_EQ(r.law.sigma_t, 1.5 * 11.5e6);
  EXPECT_DOUBLE_EQ(r.law.g_n, 1.5 * 1.5 * 900);
  EXPECT_DOUBLE_EQ(r.law.g_t, 1.5 * 1.5 * 1125);
  EXPECT_EQ(r.law.kn, 8e10);  // stiffness untouched
}

TEST(CrushRecipe, BadValuesNameFileFieldAndValue) {
  const std::string set = "[[set]]\nname = \"a\"\ndiameter = 0.02\n";
  EXPECT_NE(error_of("[crush]\nbogus = 1\n" + set).find("r.toml: crush.bogus: unknown key"),
            std::string::npos);
  // The law's values are checked where the law is (dem::validate_values), named in the message;
  // a value with a range of its own (dem::kBondStrength) as it is read.
  EXPECT_NE(error_of("[bond]\ng_t = -3\n" + set)
                .find("r.toml: bond: cohesive law: g_t: must be > 0, got -3"),
            std::string::npos);
  EXPECT_NE(
      error_of("[bond]\nsigma_n = 0\n" + set).find("r.toml: bond.sigma_n: must be > 0, got 0"),
      std::string::npos);
  EXPECT_NE(error_of("[bond]\nfriction = -0.1\n" + set)
                .find("r.toml: bond.friction: must be >= 0, got -0.1"),
            std::string::npos);
  EXPECT_NE(error_of("[crush]\nlocal_damping = 1.5\n" + set).find("1.5"), std::string::npos);
  EXPECT_NE(error_of("[cells]\ncell_size = 0.05\n" + set).find("fewer than 2 cells"),
            std::string::npos);
  EXPECT_NE(error_of(set + set).find("repeats"), std::string::npos);
  EXPECT_NE(error_of("[[set]]\nname = \"a\"\n").find("diameter"), std::string::npos);
  EXPECT_NE(
      error_of("[[set]]\nname = \"c\"\nshape = \"cylinder\"\ndiameter = 0.05\n").find("height"),
      std::string::npos);
  EXPECT_NE(
      error_of("[cells]\nstrength_factor = { uniform = [-1, 1] }\n" + set).find("strength_factor"),
      std::string::npos);
  EXPECT_NE(error_of("name = \"x\"\n").find("[[set]]"), std::string::npos);
}
