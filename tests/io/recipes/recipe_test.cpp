// Tests of recipe parsing: forms of distributions and the error messages for bad recipes.
#include "io/recipes/recipe.h"
#include "../../invalid_input_message.h"
#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;

namespace {
std::string shape_error_of(const std::string& text) {
  return invalid_input_message([&] { parse_shape_recipe(text, "r.toml"); });
}
const std::string kBlock =
    "[[fraction]]\nmethod = \"block\"\ncount = 3\nW = 0.03\nL = 0.05\nH = 0.02\n";
}  // namespace

TEST(Recipe, ParsesDistributionsAndDefaults) {
  const ShapeRecipe r = parse_shape_recipe(
      "seed = 9\nname = \"x\"\n[[fraction]]\nmethod = \"block\"\ncount = 4\n"
      "W = { uniform = [0.02, 0.04] }\nL_over_H = { lognormal = { mu = 0.4, sigma = 0.2, min = 1, "
      "max = 3 } }\n"
      "nd = { integers = [1, 3] }\n[[fraction]]\nmethod = \"hull\"\ncount = 2\ndiameter = 0.01\n"
      "roundness = [1.1, 1.2]\n",
      "r.toml");
  EXPECT_EQ(r.seed, 9u);
  ASSERT_EQ(r.fractions.size(), 2u);
  const auto& b = r.fractions[0];
  EXPECT_EQ(b.name, "block");
  EXPECT_EQ(b.count, 4);
  EXPECT_EQ(b.params.at("W").kind, Distribution::Kind::Uniform);
  EXPECT_DOUBLE_EQ(b.params.at("W").b, 0.04);
  EXPECT_EQ(b.params.at("L_over_H").kind, Distribution::Kind::Lognormal);
  EXPECT_DOUBLE_EQ(b.params.at("L_over_H").max, 3.0);
  EXPECT_EQ(b.params.at("nd").kind, Distribution::Kind::Integers);
  EXPECT_DOUBLE_EQ(r.fractions[1].params.at("roundness_min").a, 1.1);
  EXPECT_DOUBLE_EQ(r.fractions[1].params.at("roundness_max").a, 1.2);
}

TEST(Recipe, ErrorsNameFileFieldAndValue) {
  std::string e = shape_error_of(kBlock + "sl = nan\n");
  EXPECT_NE(e.find("r.toml: fraction[0].sl"), std::string::npos) << e;
  EXPECT_NE(e.find("nan"), std::string::npos) << e;
  e = shape_error_of(kBlock + "sl = 1.3\nsu = 1.1\n");
  EXPECT_NE(e.find("fraction[0].sl"), std::string::npos) << e;
  EXPECT_NE(e.find("1.3"), std::string::npos) << e;
  e = shape_error_of(kBlock + "colour = 3\n");
  EXPECT_NE(e.find("fraction[0].colour: unknown parameter"), std::string::npos) << e;
  e = shape_error_of("sead = 1\n" + kBlock);
  EXPECT_NE(e.find("r.toml: sead: unknown key"), std::string::npos) << e;
  e = shape_error_of(kBlock + "W_split = { uniform = [0.5, 1.5] }\n");
  EXPECT_FALSE(e.empty());
  e = shape_error_of(
      "[[fraction]]\nmethod = \"block\"\ncount = 3\nW = -0.03\nL = 0.05\nH = 0.02\n");
  EXPECT_NE(e.find("fraction[0].W: must be a size between 1e-30 and 1e30, got -0.03"),
            std::string::npos)
      << e;
  e = shape_error_of("[[fraction]]\nmethod = \"cube\"\ncount = 3\n");
  EXPECT_NE(e.find("fraction[0].method"), std::string::npos) << e;
  e = shape_error_of("[[fraction]]\nmethod = \"block\"\ncount = 3\nL = 0.05\nH = 0.02\n");
  EXPECT_NE(e.find("fraction[0].W: required"), std::string::npos) << e;
  e = shape_error_of("seed = 1\n");
  EXPECT_NE(e.find("no [[fraction]]"), std::string::npos) << e;
  e = shape_error_of("seed = = 1\n");
  EXPECT_NE(e.find("r.toml:1: TOML syntax error"), std::string::npos) << e;
  e = shape_error_of(kBlock + "W_split = { gauss = [1, 2] }\n");
  EXPECT_NE(e.find("unknown distribution"), std::string::npos) << e;
}

TEST(Recipe, MissingFileIsIoError) {
  EXPECT_THROW(read_shape_recipe("/nonexistent/x.toml"), IoError);
}
