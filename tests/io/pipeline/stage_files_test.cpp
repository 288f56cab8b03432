// The one resume protocol (dem/run/stage_store.h kept by io/pipeline/stage_files.h): checksummed
// stage records, fingerprints refused when they differ, and the compression and the element test
// stopped, kept in a StageFiles directory and continued to the bytes of runs never stopped.
#include "io/pipeline/stage_files.h"

#include "dem/core/timestep.h"
#include "dem/lab/element_loading.h"
#include "dem/specimen/compression.h"
#include "geom/errors.h"
#include "io/formats/checkpoint.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

using namespace clumpkit;
using namespace clumpkit::dem;
namespace fs = std::filesystem;

namespace {

fs::path stage_scratch(const std::string& name) {
  const fs::path d = fs::path(::testing::TempDir()) / ("clumpkit_stages_" + name);
  fs::remove_all(d);
  return d;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The bytes of a world's checkpoint: every body, wall, contact and list, to compare two worlds.
std::string world_bytes(const World& world, const fs::path& dir);

// Whether two worlds have the same checkpoint bytes up to the last two words (the near-list
// filter count, a statistic that counts the filter a restored world makes from its restored
// lists at its first step, and the checksum); else says where they first differ.
::testing::AssertionResult same_world(const World& a, const World& b, const fs::path& dir) {
  std::string x = world_bytes(a, dir), y = world_bytes(b, dir);
  x.resize(x.size() - 16);
  y.resize(y.size() - 16);
  if (x == y) return ::testing::AssertionSuccess();
  std::size_t k = 0;
  while (k < x.size() && k < y.size() && x[k] == y[k]) ++k;
  return ::testing::AssertionFailure()
         << "checkpoints of " << x.size() << " and " << y.size() << " bytes differ from byte " << k
         << " (steps " << a.steps() << " and " << b.steps() << ")";
}

std::string world_bytes(const World& world, const fs::path& dir) {
  const fs::path path = dir / "compare.ckpt";
  save_checkpoint(path.string(), world);
  std::string bytes = read_bytes(path);
  fs::remove(path);
  return bytes;
}

// An interrupter that asks to stop at its `nth` question (1-based), then never again.
Interrupter stop_at(int nth) {
  auto asked = std::make_shared<int>(0);
  return [asked, nth](std::string_view, double) { return ++*asked == nth; };
}

// About 130 spheres of 10 mm in a 5 d cube at n = 0.42, closed at 1e-4 strain per step (about
// 3,200 steps from the loose packing's 1.375 times the size) and relaxed for exactly 2,000 (no
// unbalanced-force rule), so both phases are asked whether to stop, every 1,000 steps.
CompressionSpec small_cube() {
  CompressionSpec s;
  s.size = Vec3::Constant(0.05);
  s.porosity = 0.42;
  s.classes = {{0.0099, 0.0101, 100.0, false}};
  s.contact.kn = 8e7;
  s.contact.ks = 8e5;
  s.contact.friction = 0.5;
  s.contact.local_damping = 0.7;
  s.loose_factor = 1.25;
  s.strain_per_step = 1e-4;
  s.relax_unbalanced = 0.0;
  s.relax_max_steps = 2000;
  s.seed = 7;
  return s;
}

}  // namespace

TEST(StageFiles, RecordsRoundTripAndADamagedOneIsRefusedNamingTheFile) {
  const fs::path d = stage_scratch("records");
  fs::create_directories(d);
  const std::string path = (d / "a.done").string();
  const StageRecord r{{"porosity", "0.41234567890123451"}, {"steps", "1200"}};
  write_stage_record(path, r);
  EXPECT_EQ(read_stage_record(path), r);
  std::string bytes = read_bytes(path);
  bytes[bytes.find("1200")] = '7';
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  try {
    read_stage_record(path);
    FAIL() << "a damaged record was read";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_stage_record(path, {{"key", "two words"}}), InvalidInput);
}

TEST(StageFiles, AResumeRefusesCheckpointsOfAnotherFingerprintAndAFreshRunEmptiesTheDirectory) {
  const fs::path d = stage_scratch("fingerprint");
  {
    StageFiles first(d.string(), false);
    first.open("aaaa");
    first.finish("one", {{"steps", "5"}}, nullptr);
  }
  StageFiles other(d.string(), true);
  try {
    other.open("bbbb");
    FAIL() << "checkpoints of another fingerprint were accepted";
  } catch (const InvalidInput& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("aaaa"), std::string::npos) << m;
    EXPECT_NE(m.find("bbbb"), std::string::npos) << m;
  }
  StageFiles same(d.string(), true);
  same.open("aaaa");
  ASSERT_TRUE(same.finished("one"));
  EXPECT_EQ(same.finished("one")->at("steps"), "5");
  StageFiles afresh(d.string(), false);
  afresh.open("aaaa");
  EXPECT_FALSE(afresh.finished("one"));
  EXPECT_FALSE(fs::exists(d / "one.done"));
}

TEST(StageFiles, CompressionStoppedWhileClosingAndWhileRelaxingResumesToTheSameBytes) {
  const CompressionSpec spec = small_cube();
  const CompressionResult straight = compress_specimen(spec);
  const fs::path d = stage_scratch("compression");
  StageControl control;
  control.checkpoint_every_seconds = 0;  // only when stopped
  // Stopped at closing step 1,000 (the first question), then at relaxation step 1,000 (the
  // first question past 0.9 of the work, the closing's share), then to the end.
  for (int run = 0; run < 2; ++run) {
    StageFiles files(d.string(), run > 0);
    control.store = &files;
    control.interrupter =
        run == 0 ? stop_at(1) : [](std::string_view, double f) { return f > 0.9; };
    EXPECT_THROW(compress_specimen(spec, control), Interrupted);
    ASSERT_TRUE(fs::exists(d / "compression.ckpt"));
  }
  CheckpointInfo info;
  const World at = load_checkpoint((d / "compression.ckpt").string(), &info);
  EXPECT_EQ(info.state.at("relax_steps"), "1000");
  StageFiles files(d.string(), true);
  control.store = &files;
  control.interrupter = {};
  const CompressionResult resumed = compress_specimen(spec, control);
  EXPECT_TRUE(same_world(resumed.world, straight.world, d));
  EXPECT_EQ(resumed.relax_steps, straight.relax_steps);
  EXPECT_EQ(resumed.compression_steps, straight.compression_steps);
  EXPECT_EQ(std::memcmp(&resumed.mean_stress, &straight.mean_stress, sizeof(double)), 0);
  // Finished: the stage's world is kept, and a resume takes it without stepping.
  EXPECT_FALSE(fs::exists(d / "compression.ckpt"));
  ASSERT_TRUE(fs::exists(d / "compression.world"));
  StageFiles again(d.string(), true);
  control.store = &again;
  control.interrupter = [](std::string_view, double) -> bool {
    ADD_FAILURE() << "a finished compression stepped again";
    return false;
  };
  EXPECT_TRUE(same_world(compress_specimen(spec, control).world, straight.world, d));
}

TEST(StageFiles, ElementTestStoppedWhileConsolidatingAndWhileLoadingResumesToTheSameCurve) {
  const CompressionResult cube = compress_specimen(small_cube());
  const auto specimen = [&] {
    CellSpecimen s{
        World(element_test_world_options(cube.world.bodies(), cube.world.options().contact)), {}};
    for (const Body& b : cube.world.bodies()) s.world.add_body(b);
    s.cell = add_cuboid_test_cell(s.world, cube.lo, cube.hi);
    s.world.options().timestep = 0.2 * critical_timestep(s.world);
    return s;
  };
  ElementTestSettings t;
  t.path = &kTriaxialPath;
  t.confining = 2.0 * cube.mean_stress;
  t.strain_rate = 2.0;
  t.max_axial_strain = 0.003;
  t.record_every = 300;
  t.consolidation_tolerance = 0.01;  // a consolidation of some thousand steps
  t.consolidation_unbalanced = 5e-3;
  t.max_consolidation_steps = 20000;
  CellSpecimen a = specimen();
  const ElementTestResult straight = run_element_test(a, t, StageControl{}, "fp");
  ASSERT_GE(straight.curve.size(), 4u);
  ASSERT_GT(straight.consolidation_steps, 1000);  // asked first while consolidating

  const fs::path d = stage_scratch("element");
  StageControl control;
  control.checkpoint_every_seconds = 0;
  int consolidated_calls = 0;
  const auto consolidated = [&](const CellSpecimen& c, const ElementTestState& st) {
    ++consolidated_calls;
    EXPECT_EQ(st.curve.size(), 1u);
    EXPECT_EQ(c.world.steps(), static_cast<std::uint64_t>(straight.consolidation_steps));
  };
  // Stopped at the first question (consolidation step 1,000), then at the 3rd of the resumed
  // run (past the consolidated state, in the loading), then to the end.
  for (int stop : {1, 3}) {
    StageFiles files(d.string(), stop > 1);
    control.store = &files;
    control.interrupter = stop_at(stop);
    CellSpecimen b = specimen();
    EXPECT_THROW(run_element_test(b, t, control, "fp", consolidated), Interrupted);
  }
  CheckpointInfo info;
  load_checkpoint((d / "test.ckpt").string(), &info);
  EXPECT_EQ(info.state.at("phase"), "2");  // loading
  StageFiles files(d.string(), true);
  control.store = &files;
  control.interrupter = {};
  CellSpecimen b = specimen();
  const ElementTestResult resumed = run_element_test(b, t, control, "fp", consolidated);
  EXPECT_TRUE(resumed.resumed);
  EXPECT_EQ(consolidated_calls, 1);
  EXPECT_EQ(resumed.consolidation_steps, straight.consolidation_steps);
  ASSERT_EQ(resumed.curve.size(), straight.curve.size());
  for (std::size_t k = 0; k < straight.curve.size(); ++k) {
    const CurveRow &x = straight.curve[k], &y = resumed.curve[k];
    EXPECT_EQ(x.step, y.step);
    for (const auto f :
         {&CurveRow::axial_strain, &CurveRow::volumetric_strain, &CurveRow::axial_stress,
          &CurveRow::lateral_stress, &CurveRow::p, &CurveRow::q, &CurveRow::porosity,
          &CurveRow::coordination, &CurveRow::unbalanced})
      EXPECT_EQ(std::memcmp(&(x.*f), &(y.*f), sizeof(double)), 0) << "row " << k;
  }
  EXPECT_TRUE(same_world(b.world, a.world, d));
  // Another fingerprint (another test, recipe or specimen) is refused, not mixed in.
  StageFiles other(d.string(), true);
  control.store = &other;
  CellSpecimen c = specimen();
  EXPECT_THROW(run_element_test(c, t, control, "another", consolidated), InvalidInput);
}
