// The element test's state and cell as a stage record and back (dem/lab/element_loading_stage.cpp,
// put_cell/read_cell of dem/lab/cell.h): exact numbers, malformed entries refused by name. The
// staged test stopped and resumed: tests/io/pipeline/stage_files_test.cpp.
#include "dem/lab/element_loading.h"

#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST(ElementTestRecord, StateAndCellRoundTripExactly) {
  ElementTestState st;
  st.phase = ElementTestState::Phase::loading;
  st.consolidation_steps = 12345;
  st.consolidated = true;
  st.loading_steps = 600;
  st.start_height = 0.1 / 3.0;
  st.height0 = 0.0333333333333333;
  st.volume0 = 1e-4 / 7.0;
  st.solid_volume = 6.3e-5;
  st.test_friction = 0.5;
  st.next_hold = 2;
  st.holding = true;
  st.hold_steps = 4321;
  for (int k = 0; k < 3; ++k) {
    CurveRow c;
    c.step = 300 * k;
    c.axial_strain = k / 7.0;
    c.volumetric_strain = -k / 11.0;
    c.axial_stress = 1e5 + k / 3.0;
    c.lateral_stress = 1e5;
    c.p = 1e5 + k / 9.0;
    c.q = k / 3.0;
    c.porosity = 0.4 - k * 1e-17;
    c.coordination = 4.25;
    c.unbalanced = k == 2 ? std::nan("") : 1e-3 * k;
    c.held = k;
    st.curve.push_back(c);
  }
  TestCell cell;
  cell.shape = TestCell::Shape::cuboid;
  cell.lateral = {0, 1, 2, 3};
  cell.bottom = 4;
  cell.top = 5;
  const StageRecord r = element_test_record(st, cell);
  ElementTestState back;
  TestCell back_cell;
  read_element_test_record(r, "checkpoint", back, back_cell);
  EXPECT_EQ(back.phase, st.phase);
  EXPECT_EQ(back.consolidation_steps, st.consolidation_steps);
  EXPECT_EQ(back.consolidated, st.consolidated);
  EXPECT_EQ(back.loading_steps, st.loading_steps);
  EXPECT_EQ(back.next_hold, 2);
  EXPECT_TRUE(back.holding);
  EXPECT_EQ(back.hold_steps, 4321);
  for (const auto f :
       {&ElementTestState::start_height, &ElementTestState::height0, &ElementTestState::volume0,
        &ElementTestState::solid_volume, &ElementTestState::test_friction})
    EXPECT_TRUE(same_bits(back.*f, st.*f));
  ASSERT_EQ(back.curve.size(), st.curve.size());
  for (std::size_t k = 0; k < st.curve.size(); ++k) {
    EXPECT_EQ(back.curve[k].step, st.curve[k].step);
    for (const auto f :
         {&CurveRow::axial_strain, &CurveRow::volumetric_strain, &CurveRow::axial_stress,
          &CurveRow::lateral_stress, &CurveRow::p, &CurveRow::q, &CurveRow::porosity,
          &CurveRow::coordination, &CurveRow::held})
      EXPECT_TRUE(same_bits(back.curve[k].*f, st.curve[k].*f)) << "row " << k;
  }
  EXPECT_TRUE(std::isnan(back.curve[2].unbalanced));
  EXPECT_EQ(back_cell.shape, cell.shape);
  EXPECT_EQ(back_cell.lateral, cell.lateral);
  EXPECT_EQ(back_cell.bottom, 4);
  EXPECT_EQ(back_cell.top, 5);
}

TEST(ElementTestRecord, MalformedRecordsAreRefusedNamingTheEntry) {
  ElementTestState st;
  st.curve.push_back(CurveRow{});
  TestCell cell;
  cell.shape = TestCell::Shape::cylinder;
  cell.lateral = {0};
  cell.bottom = 1;
  cell.top = 2;
  const StageRecord good = element_test_record(st, cell);
  const auto refused = [&](const std::string& key, const std::string& value,
                           const std::string& named) {
    StageRecord r = good;
    if (value.empty())
      r.erase(key);
    else
      r[key] = value;
    ElementTestState s;
    TestCell c;
    try {
      read_element_test_record(r, "test.ckpt", s, c);
      ADD_FAILURE() << key << " = '" << value << "' was read";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("test.ckpt"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
    }
  };
  refused("phase", "7", "phase");
  refused("curve.000000", "1,2,3", "curve.000000");
  refused("curve.rows", "2", "curve.000001");
  refused("cell.shape", "sphere", "cell.shape");
  refused("cell.lateral", "0,1", "lateral walls");  // a cylinder has one
  refused("cell.lateral", "a", "cell.lateral");
  refused("height0", "", "height0");
  refused("hold_steps", "", "hold_steps");
}
