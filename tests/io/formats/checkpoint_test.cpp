// Checkpoint round trips continue bit-identically; corrupt files are rejected; run_until resumes
// from checkpoints to the same bytes.
#include "io/formats/checkpoint.h"
#include "dem/core/timestep.h"
#include "dem/core/world.h"
#include "dem/measure/region_volume.h"
#include "dem/run/run.h"
#include "geom/errors.h"
#include "geom/random.h"
#include "tests/dem/bonded_column.h"
#include "tests/dem/deposition_world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

namespace clumpkit::dem {
namespace {

using test::make_deposition;

std::string temp_path(const std::string& name) {
  return (std::filesystem::path(::testing::TempDir()) / ("clumpkit_ckpt_" + name)).string();
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// Bit-for-bit comparison of everything that drives later steps.
void expect_identical(const World& a, const World& b) {
  EXPECT_EQ(a.steps(), b.steps());
  EXPECT_TRUE(same_bits(a.time(), b.time()));
  EXPECT_EQ(a.neighbour_builds(), b.neighbour_builds());
  ASSERT_EQ(a.bodies().size(), b.bodies().size());
  int differing = 0;
  for (std::size_t k = 0; k < a.bodies().size(); ++k) {
    const Body& x = a.bodies()[k];
    const Body& y = b.bodies()[k];
    const bool same = same_bits(x.position, y.position) && same_bits(x.velocity, y.velocity) &&
                      same_bits(x.orientation.coeffs(), y.orientation.coeffs()) &&
                      same_bits(x.angular_velocity, y.angular_velocity) &&
                      same_bits(x.force, y.force) && same_bits(x.torque, y.torque);
    differing += same ? 0 : 1;
  }
  EXPECT_EQ(differing, 0) << "bodies whose state differs in some bit";
  ASSERT_EQ(a.contacts().size(), b.contacts().size());
  for (std::size_t k = 0; k < a.contacts().size(); ++k) {
    const PairContact& x = a.contacts()[k];
    const PairContact& y = b.contacts()[k];
    ASSERT_EQ(x.i, y.i);
    ASSERT_EQ(x.j, y.j);
    EXPECT_TRUE(same_bits(x.state.shear, y.state.shear)) << "contact " << k;
    EXPECT_TRUE(same_bits(x.state.normal_force, y.state.normal_force)) << "contact " << k;
    EXPECT_TRUE(same_bits(x.state.excused, y.state.excused)) << "contact " << k;
  }
  ASSERT_EQ(a.wall_contacts().size(), b.wall_contacts().size());
  for (std::size_t k = 0; k < a.wall_contacts().size(); ++k) {
    const WallContact& x = a.wall_contacts()[k];
    const WallContact& y = b.wall_contacts()[k];
    ASSERT_EQ(x.sphere, y.sphere);
    ASSERT_EQ(x.wall, y.wall);
    EXPECT_TRUE(same_bits(x.state.shear, y.state.shear)) << "wall contact " << k;
  }
  ASSERT_EQ(a.walls().size(), b.walls().size());
  for (std::size_t k = 0; k < a.walls().size(); ++k) {
    EXPECT_TRUE(same_bits(a.walls()[k].point, b.walls()[k].point)) << "wall " << k;
    EXPECT_TRUE(same_bits(a.walls()[k].radius, b.walls()[k].radius)) << "wall " << k;
  }
}

bool any_shear(const World& w) {
  for (const PairContact& c : w.contacts())
    if (c.state.shear.squaredNorm() > 0.0) return true;
  return false;
}

TEST(DemCheckpoint, HalfRunCheckpointLoadContinuesBitIdentically) {
  constexpr int kSteps = 4000;
  World straight = make_deposition(160);
  straight.step(kSteps);

  World first = make_deposition(160);
  first.step(kSteps / 2);
  ASSERT_FALSE(first.contacts().empty());
  ASSERT_FALSE(first.wall_contacts().empty());
  ASSERT_TRUE(any_shear(first)) << "the test needs shear history at the checkpoint";
  const std::string path = temp_path("half.ckpt");
  CheckpointInfo info;
  info.stage = "deposition";
  info.state = {
      {"height_reference", "0.123456789012345"}, {"step", "42"}, {"curve.000001", "1,2.5,-3e-07"}};
  save_checkpoint(path, first, info);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));

  CheckpointInfo loaded_info;
  World resumed = load_checkpoint(path, &loaded_info);
  EXPECT_EQ(loaded_info.stage, "deposition");
  EXPECT_EQ(loaded_info.state, info.state);
  expect_identical(first, resumed);  // includes the last step's forces and contacts
  EXPECT_TRUE(same_bits(mean_unbalanced_force_ratio(first), mean_unbalanced_force_ratio(resumed)));

  resumed.step(kSteps / 2);
  expect_identical(straight, resumed);
  std::filesystem::remove(path);
}

TEST(DemCheckpoint, SizeScaledLawAndServoWallsContinueBitIdentically) {
  constexpr int kSteps = 6000;
  World straight = make_deposition(160, true, true);
  straight.step(kSteps);
  World first = make_deposition(160, true, true);
  first.step(kSteps / 2);
  ASSERT_FALSE(first.wall_contacts().empty());
  const std::string path = temp_path("scaled.ckpt");
  save_checkpoint(path, first);
  World resumed = load_checkpoint(path);
  EXPECT_EQ(resumed.options().contact.scaling, StiffnessScaling::linear);
  EXPECT_EQ(resumed.options().contact.d_ref, 0.01);
  EXPECT_EQ(resumed.walls()[0].friction, 0.0);
  EXPECT_EQ(resumed.walls()[1].radial_velocity, -0.01);
  for (std::size_t k = 0; k < first.bodies().size(); ++k)
    EXPECT_TRUE(same_bits(first.bodies()[k].diameter, resumed.bodies()[k].diameter));
  resumed.step(kSteps / 2);
  expect_identical(straight, resumed);
  EXPECT_LT(straight.walls()[1].radius, 0.05);  // the cylinder did close in
  std::filesystem::remove(path);
}

// A world that sorts its bodies (WorldOptions::sort_every) saves them in its current order and
// its interval: the resumed run sorts at the same steps, to the same bits.
TEST(DemCheckpoint, SortingWorldContinuesBitIdentically) {
  constexpr int kSteps = 4000;
  World straight = make_deposition(160);
  straight.options().sort_every = 700;
  straight.step(kSteps);
  World first = make_deposition(160);
  first.options().sort_every = 700;
  first.step(kSteps / 2);
  const std::string path = temp_path("sorting.ckpt");
  save_checkpoint(path, first);
  World resumed = load_checkpoint(path);
  EXPECT_EQ(resumed.options().sort_every, 700);
  expect_identical(first, resumed);
  resumed.step(kSteps / 2);
  expect_identical(straight, resumed);
  // The sorts did reorder the bodies (the lattice was laid y fastest, the sort puts x fastest):
  // radii, drawn at random, differ from those of the unsorted run at the same index.
  World unsorted = make_deposition(160);
  unsorted.step(kSteps);
  int differ = 0;
  for (std::size_t k = 0; k < straight.bodies().size(); ++k)
    differ += straight.bodies()[k].mass != unsorted.bodies()[k].mass;
  EXPECT_GT(differ, 50);
  std::filesystem::remove(path);
}

// A cone probe pushed into the pile: its profile and sleeve are saved, and the push continues
// to the same bits.
TEST(DemCheckpoint, ProbeWallContinuesBitIdentically) {
  auto make = [] {
    World world = make_deposition(160, false);
    world.add_wall(Wall::probe(Vec3(0.0, 0.0, 0.06), 0.012, 60.0, Vec3(0.0, 0.0, -1.0)));
    return world;
  };
  auto on_probe = [](const World& w) {
    int n = 0;
    for (const WallContact& c : w.wall_contacts()) n += c.wall == 2;
    return n;
  };
  // Saved at the first hundred steps that end with the probe touching a sphere.
  World first = make();
  int steps = 0;
  while (on_probe(first) == 0 && steps < 6000) first.step(100), steps += 100;
  ASSERT_GT(on_probe(first), 0) << "the test needs the probe in the pile at the checkpoint";
  World straight = make();
  straight.step(steps + 1500);
  const std::string path = temp_path("probe.ckpt"), again = temp_path("probe2.ckpt");
  save_checkpoint(path, first);
  World resumed = load_checkpoint(path);
  const Wall& w = resumed.walls()[2];
  EXPECT_EQ(w.kind, Wall::Kind::probe);
  EXPECT_EQ(w.profile, first.walls()[2].profile);
  EXPECT_EQ(w.sleeve_from, 1);
  save_checkpoint(again, resumed);
  EXPECT_EQ(read_bytes(path), read_bytes(again));
  resumed.step(1500);
  expect_identical(straight, resumed);
  EXPECT_LT(straight.walls()[2].point.z(), 0.045);  // the probe did go down
  std::filesystem::remove(path);
  std::filesystem::remove(again);
}

TEST(DemCheckpoint, SaveLoadSaveIsByteIdentical) {
  World world = make_deposition(160);
  world.step(2000);
  ASSERT_TRUE(any_shear(world));
  const std::string a = temp_path("a.ckpt"), b = temp_path("b.ckpt");
  save_checkpoint(a, world, {"stage two", {{"a", "5"}, {"b", "-nan"}}});
  CheckpointInfo info;
  const World loaded = load_checkpoint(a, &info);
  save_checkpoint(b, loaded, info);
  EXPECT_EQ(read_bytes(a), read_bytes(b));
  EXPECT_EQ(read_bytes(a).substr(0, 12), "CLUMPKITCKPT");
  std::filesystem::remove(a);
  std::filesystem::remove(b);
}

// Expects load_checkpoint(path) to throw InvalidInput whose message names the file.
void expect_rejected(const std::string& path, const std::string& why) {
  try {
    load_checkpoint(path);
    ADD_FAILURE() << why << ": no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << why << ": " << e.what();
  }
}

TEST(DemCheckpoint, TruncatedOrCorruptFileThrowsInvalidInputNamingTheFile) {
  World world = make_deposition(40);
  world.step(300);
  const std::string good = temp_path("good.ckpt"), bad = temp_path("bad.ckpt");
  save_checkpoint(good, world);
  const std::string bytes = read_bytes(good);
  ASSERT_GT(bytes.size(), 100u);

  for (std::size_t size : {std::size_t(0), std::size_t(5), std::size_t(12), std::size_t(16),
                           std::size_t(30), bytes.size() / 2, bytes.size() - 1}) {
    write_bytes(bad, bytes.substr(0, size));
    expect_rejected(bad, "truncated to " + std::to_string(size));
  }
  write_bytes(bad, bytes + "x");
  expect_rejected(bad, "one extra byte");

  for (std::size_t at :
       {std::size_t(0), std::size_t(12), std::size_t(40), bytes.size() / 2, bytes.size() - 3}) {
    std::string corrupt = bytes;
    corrupt[at] = static_cast<char>(corrupt[at] ^ 0x20);
    write_bytes(bad, corrupt);
    expect_rejected(bad, "byte flipped at " + std::to_string(at));
  }
  std::string other_version = bytes;
  other_version[12] = 99;
  write_bytes(bad, other_version);
  try {
    load_checkpoint(bad);
    ADD_FAILURE() << "version 99 accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("version 99"), std::string::npos) << e.what();
  }

  EXPECT_THROW(load_checkpoint(temp_path("missing.ckpt")), IoError);
  EXPECT_THROW(save_checkpoint(temp_path("no_such_dir/x.ckpt"), world), IoError);
  std::filesystem::remove(good);
  std::filesystem::remove(bad);
}

// Periodic wall-clock checkpoints leave the run unchanged, and a run killed after a
// checkpoint resumes from it to the same end state.
TEST(DemRun, PeriodicCheckpointsDoNotChangeTheResultAndResumeIdentically) {
  constexpr long kSteps = 2000;
  World plain = make_deposition(60);
  RunLimits limits;
  limits.max_steps = kSteps;
  run_until(plain, limits);

  const std::string path = temp_path("periodic.ckpt");
  World checked = make_deposition(60);
  RunLimits with_checkpoints = limits;
  with_checkpoints.checkpoint = [&](const World& w, const RunState&) {
    CheckpointInfo stage;
    stage.stage = "deposition";
    save_checkpoint(path, w, stage);
  };
  with_checkpoints.checkpoint_every_seconds = 1e-9;  // after every chunk
  struct Killed {};
  EXPECT_THROW(run_until(checked, with_checkpoints,
                         [&](std::string_view, double) -> bool {
                           if (checked.steps() == 1300) throw Killed{};
                           return false;
                         }),
               Killed);
  CheckpointInfo info;
  World resumed = load_checkpoint(path, &info);
  EXPECT_EQ(info.stage, "deposition");
  // The kill came from the interrupter at step 1300, which precedes that chunk's checkpoint
  // (rules and interrupter first, then the checkpoint): the last one is at 1200.
  EXPECT_EQ(resumed.steps(), 1200);
  RunLimits rest = with_checkpoints;
  rest.max_steps = kSteps - resumed.steps();
  EXPECT_EQ(run_until(resumed, rest).steps, kSteps - 1200);
  expect_identical(plain, resumed);
  std::filesystem::remove(path);
}

// An interrupter that asks to stop ends the run with a checkpoint of that very step, and the
// run resumed from it ends where the uninterrupted one does.
TEST(DemRun, InterruptedRunCheckpointsAndResumesIdentically) {
  constexpr long kSteps = 1500;
  World plain = make_deposition(40);
  RunLimits limits;
  limits.max_steps = kSteps;
  run_until(plain, limits);

  World stopped = make_deposition(40);
  std::optional<World> saved;
  RunLimits with_checkpoint = limits;
  with_checkpoint.checkpoint = [&](const World& w, const RunState&) { saved = w; };
  const RunOutcome out = run_until(stopped, with_checkpoint, [&](std::string_view, double f) {
    return f >= 0.4;  // at step 600
  });
  EXPECT_EQ(out.stopped_by, "interrupted");
  EXPECT_EQ(out.steps, 600);
  ASSERT_TRUE(saved.has_value());
  EXPECT_EQ(saved->steps(), 600u);
  RunLimits rest = limits;
  rest.max_steps = kSteps - out.steps;
  EXPECT_EQ(run_until(*saved, rest).stopped_by, "step_cap");
  expect_identical(plain, *saved);
}

// The settled-height rule stops a settling pack at a window boundary once its column height
// holds still, and a run resumed from a checkpoint with the saved reference stops at the same
// step as the uninterrupted one.
TEST(DemRun, SettledHeightRuleStopsAtAWindowBoundaryAndResumesWithItsReference) {
  World settling = make_deposition(40, /*platen=*/false);
  settling.options().contact.local_damping = 0.7;
  RunLimits limits;
  limits.max_steps = 200000;
  limits.height_window = 500;
  limits.height_tolerance = 1e-5;  // m; the spheres are ~1e-2 m
  std::vector<std::pair<World, RunState>> checkpoints;
  limits.checkpoint_every_seconds = 1e-9;
  limits.checkpoint = [&](const World& w, const RunState& st) {
    if (w.steps() % 700 == 0) checkpoints.emplace_back(w, st);
  };
  const World start = settling;
  const RunOutcome out = run_until(settling, limits);
  EXPECT_EQ(out.stopped_by, "settled_height");
  EXPECT_EQ(out.steps % 500, 0);
  EXPECT_LT(out.steps, limits.max_steps);
  EXPECT_LT(unbalanced_to_weight_ratio(settling), 1.0);
  EXPECT_LT(std::abs(column_height(settling) - out.state.height_reference), 1e-5);
  ASSERT_GE(checkpoints.size(), 2u);

  // Resumed from a checkpoint in the middle of a window, with its state.
  auto& [world, state] = checkpoints[checkpoints.size() / 2];
  ASSERT_NE(world.steps() % 500, 0u);
  RunLimits rest = limits;
  rest.checkpoint = {};
  rest.max_steps = limits.max_steps - static_cast<long>(world.steps());
  rest.state = state;
  const RunOutcome resumed = run_until(world, rest);
  EXPECT_EQ(resumed.stopped_by, "settled_height");
  EXPECT_EQ(world.steps(), settling.steps());
  expect_identical(settling, world);

  // The checkpoints did not change the run: without them it stops at the same step.
  World again = start;
  RunLimits plain = limits;
  plain.checkpoint = {};
  EXPECT_EQ(run_until(again, plain).steps, out.steps);
  expect_identical(settling, again);
}

}  // namespace
}  // namespace clumpkit::dem

namespace clumpkit::dem {

// The checkpoint seed of the fuzz corpus is of the current format, so fuzzing reaches the
// decoding behind the version check (a format change must regenerate it).
TEST(DemCheckpoint, BondsSurviveASaveAndLoadAndContinueBitIdentically) {
  // Bonded cells pulled past the onset of damage (so points carry damage), saved, loaded and
  // run on to failure: the same bits as the run that was never stopped.
  World straight = test::bonded_column(0.05);
  World first = test::bonded_column(0.05);
  straight.options().broken_bonds_act = first.options().broken_bonds_act = false;  // not default
  // Three interfaces opened to 1.2 onset openings each (δ_u is 1.78 of it).
  const double onset = first.options().cohesive.sigma_n / first.options().cohesive.kn;
  const int half = static_cast<int>(3 * 1.2 * onset / 0.05 / first.options().timestep);
  first.step(half);
  int partial = 0;  // points part-way down the softening branch
  for (const Bond& b : first.bonds())
    for (const BondPoint& p : b.points) partial += p.state.damage > 0.0 && p.state.damage < 1.0;
  ASSERT_GT(partial, 0);
  const std::string path = temp_path("bonds.ckpt");
  save_checkpoint(path, first, {"crush", {}});
  World resumed = load_checkpoint(path);
  ASSERT_EQ(resumed.bonds().size(), first.bonds().size());
  for (std::size_t k = 0; k < first.bonds().size(); ++k) {
    const Bond &a = first.bonds()[k], &b = resumed.bonds()[k];
    EXPECT_EQ(a.a, b.a);
    EXPECT_EQ(a.b, b.b);
    EXPECT_EQ(a.factor, b.factor);
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t q = 0; q < a.points.size(); ++q) {
      EXPECT_EQ(a.points[q].state.damage, b.points[q].state.damage);
      EXPECT_EQ(a.points[q].state.slip, b.points[q].state.slip);
      EXPECT_EQ(a.points[q].state.failure_mix, b.points[q].state.failure_mix);
    }
  }
  EXPECT_EQ(resumed.options().cohesive.g_t, first.options().cohesive.g_t);
  EXPECT_EQ(resumed.options().cohesive.friction, first.options().cohesive.friction);
  EXPECT_FALSE(resumed.options().broken_bonds_act);
  straight.step(2 * half);
  resumed.step(half);
  expect_identical(straight, resumed);
  std::filesystem::remove(path);
}

TEST(DemCheckpoint, CornerContactsSurviveASaveAndLoad) {
  // A cube with corners, tilted, pressed and sliding on a platen: the corner contacts' shear
  // history survives the checkpoint, and the run continues bit for bit.
  auto make = [] {
    WorldOptions o;
    o.gravity = Vec3(0, 0, -9.81);
    o.timestep = 1e-7;
    World w(o);
    Body b = make_sphere_body(Vec3::Zero(), 0.005, 2650);
    b.mass *= 1e6;  // heavy: it ploughs on into the platen, its corners loaded all along
    b.moments = Vec3::Constant(b.mass * 0.01 * 0.01 / 6.0);
    for (int i = 0; i < 8; ++i)
      b.vertices.emplace_back(i & 1 ? 0.005 : -0.005, i & 2 ? 0.005 : -0.005,
                              i & 4 ? 0.005 : -0.005);
    b.orientation = Eigen::AngleAxisd(0.3, Vec3::UnitX()) * Eigen::AngleAxisd(0.2, Vec3::UnitY());
    double lowest = 0;
    for (const Vec3& v : b.vertices) lowest = std::min(lowest, (b.orientation * v).z());
    b.position = Vec3(0, 0, -lowest - 1e-6);  // one corner 1 µm into the platen
    b.velocity = Vec3(0.05, 0, -0.05);
    w.add_body(b);
    w.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
    return w;
  };
  World straight = make(), first = make();
  straight.step(4000);
  first.step(2000);
  ASSERT_FALSE(first.vertex_contacts().empty());
  const std::string path = temp_path("corners.ckpt");
  save_checkpoint(path, first, {"crush", {}});
  World resumed = load_checkpoint(path);
  ASSERT_EQ(resumed.vertex_contacts().size(), first.vertex_contacts().size());
  EXPECT_EQ(resumed.vertex_contacts()[0].state.shear, first.vertex_contacts()[0].state.shear);
  EXPECT_EQ(resumed.bodies()[0].vertices, first.bodies()[0].vertices);
  resumed.step(2000);
  expect_identical(straight, resumed);
  EXPECT_EQ(resumed.vertex_contacts().size(), straight.vertex_contacts().size());
  std::filesystem::remove(path);
}

TEST(DemCheckpoint, FuzzCorpusSeedIsOfTheCurrentFormat) {
  CheckpointInfo info;
  const std::string corpus = std::string(CLUMPKIT_SOURCE_DIR) + "/tests/fuzz/corpus/checkpoint/";
  const World w = load_checkpoint(corpus + "sorted-servo-v15.ckpt", &info);
  EXPECT_EQ(read_bytes(corpus + "sorted-servo-v15.ckpt").substr(12, 4),
            std::string("\x0f\0\0\0", 4));
  EXPECT_GT(w.bodies().size(), 0u);
  EXPECT_FALSE(w.walls().empty());
  EXPECT_EQ(info.state.at("phase"), "2");
  // The bonded seed: bonds, their damage and the law's friction come back.
  const World bonded = load_checkpoint(corpus + "bonded-cells-v15.ckpt");
  EXPECT_EQ(bonded.bonds().size(), 28u);
  EXPECT_EQ(bonded.options().cohesive.friction, 0.3);
  EXPECT_TRUE(bonded.options().broken_bonds_act);  // the crushing rig's setting
}

// A checkpoint of the engine before the contact pass summed the bodies (version 10) would not
// resume to the bits of the run that wrote it: refused in one line naming both versions.
TEST(DemCheckpoint, AnOlderVersionIsRefusedNamingBoth) {
  const std::string old =
      std::string(CLUMPKIT_SOURCE_DIR) + "/tests/fuzz/corpus/checkpoint/sorted-servo-v10.ckpt";
  try {
    load_checkpoint(old);
    ADD_FAILURE() << "version 10 accepted";
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("sorted-servo-v10.ckpt"), std::string::npos) << what;
    EXPECT_NE(what.find("unsupported version 10 (expected 15)"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(DemCheckpoint, BodyZonesSurviveASaveAndLoad) {
  World world = make_deposition(30);
  for (std::size_t k = 0; k < world.bodies().size(); ++k) world.bodies()[k].zone = int(k % 3);
  const std::string path = temp_path("zones.ckpt");
  save_checkpoint(path, world, {"zones", {}});
  const World loaded = load_checkpoint(path);
  ASSERT_EQ(loaded.bodies().size(), world.bodies().size());
  for (std::size_t k = 0; k < world.bodies().size(); ++k)
    EXPECT_EQ(loaded.bodies()[k].zone, int(k % 3));
  std::filesystem::remove(path);
}

}  // namespace clumpkit::dem
