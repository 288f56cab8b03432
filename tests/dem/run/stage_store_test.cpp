// Stage records (dem/run/stage_store.h): numbers read back exactly, malformed ones refused; the
// periodic and interrupt checkpoints of StageCheckpoints. The staged runs resumed from files:
// tests/io/pipeline/stage_files_test.cpp.
#include "dem/run/stage_store.h"

#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// A store that counts the checkpoints it is given.
struct CountingStore : StageStore {
  int saved = 0;
  CheckpointInfo last;
  bool keeps_checkpoints() const override { return true; }
  void checkpoint(const std::string&, const World&, const CheckpointInfo& info) override {
    ++saved;
    last = info;
  }
};

}  // namespace

TEST(StageRecord, NumbersReadBackExactlyAndMalformedOnesAreRefusedNamingTheKey) {
  StageRecord r;
  const std::vector<double> values = {0.1, -1.0 / 3.0, 6.02214076e23, 5e-324,
                                      std::numeric_limits<double>::infinity()};
  for (std::size_t k = 0; k < values.size(); ++k) put_number(r, "v" + std::to_string(k), values[k]);
  for (std::size_t k = 0; k < values.size(); ++k)
    EXPECT_TRUE(same_bits(record_number(r, "v" + std::to_string(k), "here"), values[k])) << k;
  put_number(r, "nan", std::nan(""));
  EXPECT_TRUE(std::isnan(record_number(r, "nan", "here")));
  r["steps"] = "123456789012";
  EXPECT_EQ(record_integer(r, "steps", "here"), 123456789012LL);
  r["bad"] = "1.5x";
  try {
    record_number(r, "bad", "stage layer-0");
    FAIL() << "a malformed number was read";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("stage layer-0"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad"), std::string::npos) << e.what();
  }
  EXPECT_THROW(record_integer(r, "v0", "here"), InvalidInput);  // 0.1 is not an integer
  EXPECT_THROW(record_number(r, "missing", "here"), InvalidInput);
}

TEST(StageCheckpoints, SavesWhenThePeriodPassesAndWhenAskedToStop) {
  CountingStore store;
  StageControl control;
  control.checkpoint_every_seconds = 0;  // no periodic checkpoints
  bool stop = false;
  control.interrupter = [&](std::string_view stage, double fraction) {
    EXPECT_EQ(stage, "test");
    EXPECT_GE(fraction, 0.0);
    EXPECT_LE(fraction, 1.0);
    return stop;
  };
  World world;
  StageCheckpoints checkpoints(store, control, "the-stage");
  const auto state = [] { return StageRecord{{"step", "7"}}; };
  EXPECT_FALSE(checkpoints.check(world, state, "test", 2.0));  // fraction clamped
  EXPECT_EQ(store.saved, 0);
  stop = true;
  EXPECT_TRUE(checkpoints.check(world, state, "test", 0.5));
  EXPECT_EQ(store.saved, 1);
  EXPECT_EQ(store.last.stage, "the-stage");
  EXPECT_EQ(store.last.state.at("step"), "7");
  stop = false;
  control.checkpoint_every_seconds = 1e-12;  // every check
  EXPECT_FALSE(checkpoints.check(world, state, "test", 0.5));
  EXPECT_EQ(store.saved, 2);
  // A store that keeps nothing is never asked for the state.
  StageStore none;
  StageCheckpoints quiet(none, control, "x");
  stop = true;
  EXPECT_TRUE(quiet.check(
      world,
      [] {
        ADD_FAILURE() << "state asked of a store that keeps no checkpoints";
        return StageRecord{};
      },
      "test", 0.5));
}
