// Tests of specimen recipes: bundled recipes parse, bad ones fail before any simulation with the
// file, field and value in one line.
#include "io/recipes/specimen_recipe.h"
#include "../../invalid_input_message.h"
#include "geom/errors.h"
#include "io/recipes/specimen_build.h"

#include "good_specimen_recipe.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace clumpkit;

namespace {
const std::string kDir = std::string(CLUMPKIT_SOURCE_DIR) + "/assets/recipes/";

std::string specimen_error_of(const std::string& text) {
  // Relative paths resolve in assets/recipes.
  return invalid_input_message([&] { parse_specimen_recipe(text, kDir + "test.toml"); });
}

const std::string& kGood = kGoodSpecimenRecipe;

std::string with(const std::string& from, const std::string& to) {
  std::string s = kGood;
  s.replace(s.find(from), from.size(), to);
  return s;
}
}  // namespace

TEST(SpecimenRecipe, BundledRockfillAndItsControlDifferOnlyInTheBonds) {
  // Hu et al. 2023's particles and Table 1's 6.5 mm cells with the calibrated law; the control
  // has the same everything with bonds that cannot fail (the same stiffness).
  const SpecimenRecipe a = read_specimen_recipe(kDir + "rockfill-crushable.toml");
  const SpecimenRecipe b = read_specimen_recipe(kDir + "rockfill-unbreakable.toml");
  EXPECT_TRUE(a.crushable);
  EXPECT_FALSE(a.unbreakable);
  EXPECT_TRUE(b.unbreakable);
  EXPECT_EQ(a.container_diameter, 0.15);
  EXPECT_EQ(a.sieves.front(), 0.040);
  EXPECT_EQ(a.sieves.back(), 0.020);
  EXPECT_EQ(a.crushable_material.cells.cell_size, 0.0065);
  EXPECT_EQ(a.crushable_material.shape.planes, 30);
  EXPECT_EQ(a.bond_scale, 1.85);
  EXPECT_DOUBLE_EQ(a.bond.sigma_n, 9e6 * 1.85);
  EXPECT_EQ(b.bond.kn, a.bond.kn);
  EXPECT_EQ(b.bond.kt, a.bond.kt);
  EXPECT_EQ(b.bond.sigma_n, 1e6 * a.bond.sigma_n);
  EXPECT_EQ(b.seed, a.seed);
  EXPECT_EQ(b.compression_porosity, a.compression_porosity);
}

TEST(SpecimenRecipe, BundledRecipesParse) {
  const SpecimenRecipe full = read_specimen_recipe(kDir + "srm40-triaxial.toml");
  EXPECT_DOUBLE_EQ(full.container_diameter, 0.3);
  EXPECT_EQ(full.layers, 3);
  double sum = 0, rock = 0;
  for (const auto& c : full.classes) {
    sum += c.percent;
    if (c.min >= 0.02 - 1e-12) rock += c.percent;
  }
  EXPECT_NEAR(sum, 100.0, 1e-9);
  EXPECT_NEAR(rock, 40.0, 1e-9);
  EXPECT_TRUE(std::filesystem::exists(full.library_recipe));
  // CTGU 2017's CPT group A: a 90° segment of the 300 mm chamber, 216 mm high, 6 mm spheres.
  const SpecimenRecipe cpt = read_specimen_recipe(kDir + "cpt-A.toml");
  EXPECT_TRUE(cpt.segment && cpt.compression);
  EXPECT_EQ(cpt.segment_angle_deg, 90.0);
  EXPECT_EQ(cpt.container_diameter, 0.3);
  EXPECT_EQ(cpt.container_height, 0.216);
  EXPECT_EQ(cpt.compression_porosity, 0.36);
  EXPECT_EQ(cpt.zones.regions.size(), 1u);
  // The full chambers: whole cylinders of 600 mm (R_d 33.3 for the 18 mm cone), each its
  // segment's zones inside 150 mm, then 24 mm spheres (λ 4) to the wall in the zoned groups.
  for (const char* group : {"A", "B", "C", "D", "E"}) {
    SCOPED_TRACE(group);
    const SpecimenRecipe seg = read_specimen_recipe(kDir + "cpt-" + group + ".toml");
    const SpecimenRecipe full = read_specimen_recipe(kDir + "cpt-" + group + "-full.toml");
    EXPECT_FALSE(full.segment);
    EXPECT_TRUE(full.compression);
    EXPECT_EQ(full.container_diameter, 0.6);
    EXPECT_GE(full.container_diameter / 0.018, 33.0);
    EXPECT_EQ(full.container_height, seg.container_height);
    EXPECT_EQ(full.kn, seg.kn);
    EXPECT_EQ(full.linear_scaling, seg.linear_scaling);
    EXPECT_EQ(full.d_ref, seg.d_ref);
    const auto& zs = seg.zones.regions;
    const auto& zf = full.zones.regions;
    const bool zoned = zs.size() > 1;
    ASSERT_EQ(zf.size(), zs.size() + (zoned ? 1 : 0));
    for (std::size_t k = 0; k + 1 < zs.size(); ++k) {
      EXPECT_EQ(zf[k].outer, zs[k].outer);
      EXPECT_EQ(zf[k].mixed, zs[k].mixed);
      EXPECT_EQ(zf[k].scale, zs[k].scale);
    }
    EXPECT_EQ(zf.back().outer, 0.3);
    EXPECT_EQ(zf.back().scale, zoned ? 4.0 : 1.0);
  }
  const SpecimenRecipe quick = read_specimen_recipe(kDir + "quick-specimen.toml");
  EXPECT_EQ(quick.layers, 2);
  EXPECT_EQ(quick.classes.size(), 2u);
}

TEST(SpecimenRecipe, BadRecipesFailBeforeSimulation) {
  EXPECT_EQ(specimen_error_of(kGood), "");
  std::string e = specimen_error_of("target_relative_density = 1.2\n" + kGood);
  EXPECT_NE(e.find("test.toml: target_relative_density: must be in [0, 1], got 1.2"),
            std::string::npos)
      << e;
  e = specimen_error_of("target_relative_density = -0.1\n" + kGood);
  EXPECT_NE(e.find("target_relative_density"), std::string::npos) << e;
  e = specimen_error_of(with("passing = [100, 80, 60, 40, 20]", "passing = [95, 80, 60, 40, 20]"));
  EXPECT_NE(e.find("gradation.passing[0]: the class percentages must sum to 100"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("95"), std::string::npos) << e;
  e = specimen_error_of(with("diameter = 0.3", "diameter = 0.05"));
  EXPECT_NE(e.find("container.diameter: not wider than twice the largest particle"),
            std::string::npos)
      << e;
  e = specimen_error_of(with("recipe = \"srm-rock-blocks.toml\"", "library = \"no-such-library\""));
  EXPECT_NE(e.find("rock.library: no clump library"), std::string::npos) << e;
  e = specimen_error_of(with("recipe = \"srm-rock-blocks.toml\"", "recipe = \"missing.toml\""));
  EXPECT_NE(e.find("rock.recipe: file not found"), std::string::npos) << e;
  e = specimen_error_of("colour = 1\n" + kGood);
  EXPECT_NE(e.find("colour: unknown key"), std::string::npos) << e;
  e = specimen_error_of("rock_mass_fraction = nan\n" + with("rock_mass_fraction = 0.4\n", ""));
  EXPECT_NE(e.find("rock_mass_fraction: must be finite, got nan"), std::string::npos) << e;
  e = specimen_error_of(with("rock_mass_fraction = 0.4", "rock_mass_fraction = 0.3"));
  EXPECT_NE(e.find("the gradation gives 40 %"), std::string::npos) << e;
  e = specimen_error_of(with("passing = [100, 80, 60, 40, 20]", "passing = [100, 80, 90, 40, 20]"));
  EXPECT_NE(e.find("must not increase"), std::string::npos) << e;
  // The container's lengths: the specs' one range (dem::kContainerLength), named by key.
  e = specimen_error_of(with("diameter = 0.3", "diameter = -0.3"));
  EXPECT_NE(e.find("test.toml: container.diameter: must be > 0, got -0.3"), std::string::npos) << e;
  e = specimen_error_of(with("diameter = 0.3", "shape = \"cuboid\"\nsize = [0.3, 0, 0.3]") +
                        "[preparation]\nmethod = \"compression\"\n");
  EXPECT_NE(e.find("test.toml: container.size[1]: must be > 0, got 0"), std::string::npos) << e;
}

// A segment of the chamber: compression only, its angle in (0, 180] degrees.
TEST(SpecimenRecipe, SegmentContainerIsACompressedSectorOfItsCylinder) {
  const std::string prep = "[preparation]\nmethod = \"compression\"\nporosity = 0.4\n";
  const std::string seg = "diameter = 0.3\nshape = \"segment\"\nangle = 90";
  const SpecimenRecipe r =
      parse_specimen_recipe(with("diameter = 0.3", seg) + prep, kDir + "test.toml");
  EXPECT_TRUE(r.segment);
  EXPECT_FALSE(r.cuboid);
  EXPECT_EQ(r.segment_angle_deg, 90.0);
  const dem::CompressionSpec c = compression_spec(r, {});
  EXPECT_EQ(c.shape, dem::CompressionSpec::Shape::segment);
  EXPECT_NEAR(c.angle, 3.14159265358979323846 / 2, 1e-15);
  std::string e = specimen_error_of(with("diameter = 0.3", seg));  // deposition
  EXPECT_NE(e.find("container.shape: a segment needs preparation.method"), std::string::npos) << e;
  e = specimen_error_of(with("diameter = 0.3", "diameter = 0.3\nshape = \"segment\"\nangle = 200") +
                        prep);
  EXPECT_NE(e.find("container.angle: must be in (0, 180], got 200"), std::string::npos) << e;
  e = specimen_error_of(with("diameter = 0.3", "diameter = 0.3\nangle = 90") + prep);
  EXPECT_NE(e.find("container.angle: is for shape = \"segment\""), std::string::npos) << e;
  // The target porosity's one range (dem::kTargetPorosity), named by its key.
  for (const char* n : {"0.95", "0.1"}) {
    std::string loose = prep;
    loose.replace(loose.find("0.4"), 3, n);
    e = specimen_error_of(with("diameter = 0.3", seg) + loose);
    EXPECT_NE(
        e.find("test.toml: preparation.porosity: must be in (0.2, 0.9), got " + std::string(n)),
        std::string::npos)
        << e;
  }
}

// [zones]: CTGU 2017's group E layout reaches the spec; every bad layout fails naming the field.
TEST(SpecimenRecipe, ZonesReachTheSpecAndBadLayoutsFailBeforeSimulation) {
  const std::string cpt = R"(
soil_rock_threshold = 1.0
rock_mass_fraction = 0.0
[container]
shape = "segment"
angle = 90
diameter = 0.3
height = 0.216
[preparation]
method = "compression"
porosity = 0.36
[gradation]
sieves = [0.00601, 0.00599]
passing = [100, 0]
[zones]
coordinate = "radial"
mixed_porosity = 0.33
[[zones.region]]
outer = 0.075
scale = 1
[[zones.region]]
mixed = true
outer = 0.115
small_volume_fraction = 0.37
[[zones.region]]
outer = 0.150
scale = 3
)";
  const SpecimenRecipe r = parse_specimen_recipe(cpt, kDir + "test.toml");
  ASSERT_EQ(r.zones.regions.size(), 3u);
  EXPECT_EQ(r.zones.regions[1].mixed, true);
  EXPECT_EQ(r.zones.regions[1].small_fraction, 0.37);
  EXPECT_EQ(r.zones.regions[1].small_fraction_outer, 0.37);
  EXPECT_EQ(r.zones.regions[2].scale, 3.0);
  EXPECT_EQ(r.zone_warnings.size(), 1u);  // λ 3 next to 1: allowed, with a warning
  const dem::CompressionSpec c = compression_spec(r, {});
  EXPECT_EQ(c.zones.regions.size(), 3u);
  EXPECT_EQ(c.mixed_porosity, 0.33);
  // A depth layout defaults its origin to the container's top.
  std::string depth = cpt;
  depth.replace(depth.find("\"radial\""), 8, "\"depth\"");
  EXPECT_EQ(parse_specimen_recipe(depth, kDir + "test.toml").zones.origin.z(), 0.216);

  // Each case: (from, to) edits of the recipe, then the expected message.
  const auto error = [&](const std::vector<std::string>& edits) {
    std::string s = cpt;
    for (std::size_t k = 0; k + 1 < edits.size(); k += 2)
      s.replace(s.find(edits[k]), edits[k].size(), edits[k + 1]);
    try {
      parse_specimen_recipe(s, kDir + "test.toml");
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string file = kDir + "test.toml: ";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"outer = 0.115", "outer = 0.07"}, "zones: region 2: outer bound 0.07 m must exceed"},
      {{"scale = 3", "scale = 4", "outer = 0.115", "outer = 0.125"},
       "neighbouring zones' sizes may differ 3 times at most"},
      {{"outer = 0.115", "outer = 0.100"}, "narrower than two of its large particles"},
      {{"scale = 1\n", "scale = 2\n"}, "the core's scale must be 1"},
      {{"small_volume_fraction = 0.37", "small_volume_fraction = 1.5"},
       "zones.region[2].small_volume_fraction: must be in [0, 1]"},
      {{"small_volume_fraction = 0.37", "scale = 2"}, "zones.region[2].scale: a mixed layer"},
      {{"coordinate = \"radial\"", "coordinate = \"polar\""}, "zones.coordinate: expected"},
      {{"coordinate = \"radial\"", "coordinate = \"spherical\""}, "zones.origin: needed by"},
      {{"mixed_porosity = 0.33", "mixed_porosity = 1.2"}, "zones.mixed_porosity: must be in"},
      {{"mixed_porosity = 0.33", "thickness = 3"}, "zones.thickness: unknown key"},
      {{"method = \"compression\"", "method = \"deposition\"", "shape = \"segment\"\nangle = 90\n",
        "", "porosity = 0.36\n", ""},
       "zones: need preparation.method"},
  };
  for (const auto& [edit, expected] : cases) {
    const std::string e = error(edit);
    EXPECT_EQ(e.rfind(file, 0), 0u) << e;  // one line naming the file first
    EXPECT_NE(e.find(expected), std::string::npos) << edit[1] << ": " << e;
    if (edit[1] == "scale = 4") {
      EXPECT_NE(e.find("zones: region 3: scale 4 next to 1"), std::string::npos) << e;
    }
  }
}
