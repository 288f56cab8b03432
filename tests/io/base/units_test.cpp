#include "io/base/units.h"

#include "geom/errors.h"

#include <gtest/gtest.h>

#include <set>

namespace clumpkit {
namespace {

TEST(Units, HeaderCellsCarryTheUnitAndReadersTakeOldNames) {
  EXPECT_EQ(unit_cell("volume", "m3"), "volume[m3]");
  EXPECT_EQ(unit_cell("fraction", ""), "fraction");
  EXPECT_EQ(column_name("volume[m3]"), "volume");
  EXPECT_EQ(column_unit("volume[m3]"), "m3");
  EXPECT_EQ(column_name("porosity[1]"), "porosity");
  EXPECT_EQ(column_unit("porosity[1]"), "1");
  EXPECT_EQ(column_unit("fraction"), "");
  // Folders written before units: the suffixed SI names read as today's bare ones.
  EXPECT_EQ(column_name("axial_stress_pa"), "axial_stress");
  EXPECT_EQ(column_name("depth_m"), "depth");
  EXPECT_EQ(column_name("qc_pa"), "qc");
  EXPECT_EQ(column_name("porosity"), "porosity");
  EXPECT_EQ(column_names({"x[mm]", "r", "q_pa"}), (std::vector<std::string>{"x", "r", "q"}));
}

TEST(Units, CsvHeaderTakesEachUnitFromTheVocabularyInTheLengthUnitAsked) {
  EXPECT_EQ(csv_header("library", "id,fraction,volume,area,sphericity", si_length()),
            "id[1],fraction,volume[m3],area[m2],sphericity[1]");
  EXPECT_EQ(csv_header("clump", "x,y,z,r", LengthUnit{}), "x[L],y[L],z[L],r[L]");
  EXPECT_EQ(csv_header("clump", "x,y,z,r", length_unit("mm")), "x[mm],y[mm],z[mm],r[mm]");
  // A file kind overrides the bare name: q is a stress in a curve, a quaternion elsewhere.
  EXPECT_EQ(csv_header("curve", "step,q,porosity", si_length()), "step[1],q[Pa],porosity[1]");
  EXPECT_EQ(csv_header("specimen", "I1,mass", si_length()), "I1[kg.m2],mass[kg]");
  EXPECT_EQ(csv_header("library", "I1", si_length()), "I1[m5]");
  // Numbered families.
  EXPECT_EQ(csv_header("curve", "broken_class_12", si_length()), "broken_class_12[1]");
  // A name the vocabulary lacks stays bare (the output tests then fail for it).
  EXPECT_EQ(csv_header("curve", "no_such_column", si_length()), "no_such_column");
}

TEST(Units, JsonUnitsMapHoldsEveryNumberByItsPathAndTheLongestTailWins) {
  nlohmann::ordered_json doc = {
      {"seed", 3},
      {"units", "free text of an older writer"},
      {"name", "x"},
      {"container", {{"diameter", 0.1}, {"height", 0.2}}},
      {"contact", {{"kn", 1e6}}},
      {"crushable", {{"bond_law", {{"kn", 1e13}, {"g_n", 20.0}}}}},
      {"seconds", {{"layer-0", 1.5}, {"total", 3.0}}},
      {"fractions", {{{"count", 2}, {"first_id", 0}}, {{"count", 1}, {"first_id", 2}}}},
  };
  add_units(doc, si_length());
  const nlohmann::json u = doc["units"];
  EXPECT_EQ(u["seed"], "1");
  EXPECT_EQ(u["container.diameter"], "m");
  EXPECT_EQ(u["contact.kn"], "N/m");
  EXPECT_EQ(u["crushable.bond_law.kn"], "N/m3");
  EXPECT_EQ(u["crushable.bond_law.g_n"], "J/m2");
  EXPECT_EQ(u["seconds.layer-0"], "s");
  EXPECT_EQ(u["fractions.count"], "1");
  EXPECT_FALSE(u.contains("name"));  // text
  EXPECT_EQ(u.size(), 10u);
  // The lookup readers use: the longest tail of a path.
  EXPECT_EQ(json_unit(u, {"container", "diameter"}), "m");
  EXPECT_EQ(json_unit({{"volume", "m3"}}, {"descriptors", "volume"}), "m3");
  EXPECT_EQ(json_unit({{"volume", "m3"}, {"descriptors.volume", "mm3"}}, {"descriptors", "volume"}),
            "mm3");
  EXPECT_EQ(json_unit(nlohmann::json("old text"), {"volume"}), "");
}

TEST(Units, LengthUnitNamesAreShortWordsAndEveryVocabularyUnitIsWellFormed) {
  EXPECT_EQ(length_unit("mm").pow(3), "mm3");
  EXPECT_EQ(LengthUnit{}.pow(1), "L");
  for (const char* bad : {"", "m m", "m3", "verylongunit", "../x"})
    EXPECT_THROW(length_unit(bad), InvalidInput) << bad;
  std::set<std::string> seen;
  for (const auto& [key, unit] : unit_table()) {
    EXPECT_TRUE(seen.insert(key).second) << "twice in the vocabulary: " << key;
    EXPECT_EQ(unit.find(' '), std::string::npos) << key;
    EXPECT_EQ(unit.find('['), std::string::npos) << key;
  }
}

}  // namespace
}  // namespace clumpkit
