// The recipes' ranges are the engine's: a value the engine takes is read, one it refuses is
// refused at read time in the words of the engine's own Range (its text() in the message and in
// the reference).
#include "../../invalid_input_message.h"
#include "dem/core/contact.h"
#include "dem/core/timestep.h"
#include "dem/lab/weibull.h"
#include "dem/specimen/compression.h"
#include "dem/specimen/specimen.h"
#include "geom/shapes/polyhedron.h"
#include "geom/shapes/primitives.h"
#include "io/recipes/crush_recipe.h"
#include "io/recipes/lab_recipe.h"
#include "io/recipes/recipe.h"
#include "io/recipes/specimen_recipe.h"

#include "good_specimen_recipe.h"

#include <gtest/gtest.h>

#include <string>

using namespace clumpkit;

namespace {

const std::string kRangesDir = std::string(CLUMPKIT_SOURCE_DIR) + "/assets/recipes/";

// A deposited specimen of library clumps (relative paths resolve in assets/recipes): `top` holds
// top-level keys, put before any table; `tables` follows [rock] (its keys, or tables of their own).
std::string ranges_recipe(const std::string& top, const std::string& tables) {
  return top + kGoodSpecimenRecipe + tables;
}

SpecimenRecipe ranges_parse(const std::string& text) {
  return parse_specimen_recipe(text, kRangesDir + "test.toml");
}

std::string ranges_error_of(const std::string& text) {
  return invalid_input_message([&] { ranges_parse(text); });
}

// The reference's range of key `name` in `keys`.
template <class Keys>
std::string ranges_quoted(const Keys& keys, const std::string& name) {
  for (const auto& k : keys)
    if (k.name == name) return k.range;
  return "no key " + name;
}

}  // namespace

TEST(RecipeRanges, RefusalsQuoteTheEnginesRange) {
  const std::string file = kRangesDir + "test.toml: ";
  // zones.mixed_porosity: the compression's target porosity, not [0, 1).
  std::string e = ranges_error_of(ranges_recipe("", "[zones]\nmixed_porosity = 0.95\n"));
  EXPECT_NE(e.find(file + "zones.mixed_porosity: must be in " + dem::kTargetPorosity.text() +
                   ", got 0.95"),
            std::string::npos)
      << e;
  // [rock] planes: the polyhedron's [0, 10000], checked even without crushable particles.
  EXPECT_EQ(ranges_parse(ranges_recipe("", "planes = 0\n")).crushable_material.shape.planes, 0);
  e = ranges_error_of(ranges_recipe("", "planes = 10001\n"));
  EXPECT_NE(e.find(file + "rock.planes: must be an " + kPolyhedronPlanes.text() + ", got 10001"),
            std::string::npos)
      << e;
  e = ranges_error_of(ranges_recipe("", "E = 1.5\n"));
  EXPECT_NE(e.find(file + "rock.E: must be in " + kAxisRatio.text() + ", got 1.5"),
            std::string::npos)
      << e;
  // The offsets together, as validate(PolyhedronParams) checks them, naming the field.
  e = ranges_error_of(ranges_recipe("", "offset_min = 0.8\noffset_max = 0.7\n"));
  EXPECT_NE(e.find(file + "rock: polyhedron: offset_max: must be in [0.8, 1], got 0.7"),
            std::string::npos)
      << e;
  // preparation.friction: any μ the compression takes (dem::kFriction), 11 too.
  const SpecimenRecipe r = ranges_parse(ranges_recipe(
      "", "[preparation]\nmethod = \"compression\"\nporosity = 0.4\nfriction = 11\n"));
  EXPECT_EQ(r.compression_friction, 11.0);
  e = ranges_error_of(ranges_recipe(
      "", "[preparation]\nmethod = \"compression\"\nporosity = 0.4\nfriction = -1\n"));
  EXPECT_NE(e.find(file + "preparation.friction: must be " + dem::kFriction.text() + ", got -1"),
            std::string::npos)
      << e;
  // layers: the deposition's [1, 100].
  e = ranges_error_of(ranges_recipe("layers = 0\n", ""));
  EXPECT_NE(e.find(file + "layers: must be an " + dem::kSpecimenLayers.text() + ", got 0"),
            std::string::npos)
      << e;
  // calibration_frictions: the deposition's count, each in kFriction.
  e = ranges_error_of(ranges_recipe("calibration_frictions = [0, 0.1, 0.2]\n", ""));
  EXPECT_NE(e.find(file + "calibration_frictions: need at least " +
                   std::to_string(dem::kMinCalibrationFrictions) + " values"),
            std::string::npos)
      << e;
  e = ranges_error_of(ranges_recipe("calibration_frictions = [0, 0.1, 0.2, 0.3, -0.4, 0.8]\n", ""));
  EXPECT_NE(e.find(file + "calibration_frictions[4]: must be " + dem::kFriction.text()),
            std::string::npos)
      << e;
}

TEST(RecipeRanges, CrushAndFillKeysQuoteTheEnginesRange) {
  // A crushing cylinder's sides: make_cylinder's range.
  const std::string set =
      "[[set]]\nname = \"b\"\nshape = \"cylinder\"\ndiameter = 0.05\n"
      "height = 0.025\n";
  const std::string e =
      invalid_input_message([&] { parse_crush_recipe(set + "sides = 100001\n", "r.toml"); });
  EXPECT_NE(e.find("r.toml: set[0].sides: must be an " + kCylinderSides.text() + ", got 100001"),
            std::string::npos)
      << e;
  // [fill] spheres: a sphere budget, when given, is at least one (0 is the fill's "none").
  const std::string fill = invalid_input_message([] {
    parse_shape_recipe("[[fraction]]\nmethod = \"polyhedron\"\ncount = 1\n[fill]\nspheres = 0\n",
                       "s.toml");
  });
  EXPECT_NE(fill.find("s.toml: fill.spheres: must be an " + kSphereBudget.text() + ", got 0"),
            std::string::npos)
      << fill;
}

TEST(RecipeRanges, TheReferenceQuotesTheEnginesRange) {
  EXPECT_EQ(ranges_quoted(preparation_section().keys, "porosity"), dem::kTargetPorosity.text());
  EXPECT_EQ(ranges_quoted(preparation_section().keys, "friction"), dem::kFriction.text());
  EXPECT_EQ(ranges_quoted(zones_section().keys, "mixed_porosity"), dem::kTargetPorosity.text());
  EXPECT_EQ(ranges_quoted(contact_section().keys, "friction"), dem::kFriction.text());
  EXPECT_EQ(ranges_quoted(specimen_top_section().keys, "layers"), dem::kSpecimenLayers.text());
  EXPECT_EQ(ranges_quoted(rock_section().keys, "planes"), kPolyhedronPlanes.text());
  EXPECT_EQ(ranges_quoted(rock_section().keys, "spheres_per_cell"), dem::kCellSpheres.text());
  EXPECT_EQ(ranges_quoted(rock_section().keys, "cell_voxels"), dem::kCellVoxels.text());
  EXPECT_EQ(ranges_quoted(set_section().keys, "sides"), kCylinderSides.text());
  EXPECT_EQ(ranges_quoted(bond_section().keys, "friction"), dem::kFriction.text());
  EXPECT_EQ(ranges_quoted(fill_section().keys, "spheres"), kSphereBudget.text());
  EXPECT_EQ(ranges_quoted(fill_section().keys, "voxels"), kFieldVoxels.text());
  EXPECT_EQ(ranges_quoted(fill_section().keys, "refine_iterations"), kRefineIterations.text());
  EXPECT_EQ(ranges_quoted(fraction_section().keys, "count"), kFractionCount.text());
  EXPECT_EQ(ranges_quoted(contact_section().keys, "ks"), dem::kShearStiffness.text());
  EXPECT_EQ(ranges_quoted(container_section().keys, "angle"), dem::kSegmentAngleDegrees.text());
  EXPECT_EQ(ranges_quoted(test_section().keys, "inertial_number"), dem::kHeldInertialNumber.text());
  EXPECT_EQ(ranges_quoted(test_section().keys, "max_axial_strain"), dem::kMaxAxialStrain.text());
  EXPECT_EQ(ranges_quoted(test_section().keys, "timestep_safety"), dem::kTimestepSafety.text());
  EXPECT_EQ(ranges_quoted(test_section().keys, "density_scaling"), dem::kDensityScaling.text());
  EXPECT_EQ(ranges_quoted(crush_section().keys, "timestep_safety"), dem::kTimestepSafety.text());
  EXPECT_EQ(ranges_quoted(crush_section().keys, "bootstrap"), dem::kBootstrapResamples.text());
  EXPECT_EQ(ranges_quoted(bond_section().keys, "sigma_n"), dem::kBondStrength.text());
}
