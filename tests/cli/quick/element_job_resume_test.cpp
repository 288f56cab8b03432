// `clumpkit test` stopped and resumed (issue 16 acceptance 4): in the `quick` label, outside the
// sanitizer pass, for its four runs of the test.
#include "../cli_helpers.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <cstdio>
#include <string>

namespace fs = std::filesystem;
using namespace cli_test;

namespace {

const char* kTriaxial = R"([test]
confining = 100e3
strain_rate = 0.5
max_axial_strain = 0.03
record_every = 400
)";

}  // namespace

TEST(CliQuickElementTest, StoppedOrKilledThenResumedEndsByteIdentical) {
  // Issue 16 acceptance 4: a SIGTERM at a random time (a checkpoint at the next record) and a
  // SIGKILL (the last periodic checkpoint, every 0.5 s) each followed by --resume end with the
  // bytes of an uninterrupted run; nothing is at --out before the end.
  const fs::path d = scratch();
  ASSERT_NO_FATAL_FAILURE(build_tiny_specimen(d));
  write(d / "tri.toml", kTriaxial);
  const std::string base =
      "test triaxial --quiet --threads 2 --checkpoint-seconds 0.5 --specimen " +
      (d / "spec").string() + " --recipe " + (d / "tri.toml").string() + " --out ";
  Result r;
  const double straight = timed([&] { r = run_cli(base + (d / "a").string(), d); });
  ASSERT_EQ(r.rc, 0) << r.err;
  const double when = random_seconds(0.2, 0.8 * straight);
  std::printf("SIGTERM after %.2f s of a %.1f s test\n", when, straight);
  const int rc = run_cli_stopped_after(base + (d / "b").string(), d, when);
  EXPECT_TRUE(rc == 130 || rc == 143 || rc == 0) << rc << slurp(d / "stopped.err");
  if (rc == 130) {
    EXPECT_NE(slurp(d / "stopped.err").find("continue with --resume"), std::string::npos);
    EXPECT_FALSE(fs::exists(d / "b"));
  }
  if (rc != 0) {
    r = run_cli(base + (d / "b").string() + " --resume", d);
    ASSERT_EQ(r.rc, 0) << r.err;
  }
  // The kill comes at 40 % of the straight run's time; on a machine whose load changes the
  // run may finish first (timeout's status 0, not 137), and then there is nothing to resume.
  const std::string kill = "timeout -s KILL " + std::to_string(0.4 * straight) + " " +
                           std::string(CLUMPKIT_BINARY) + " " + base + (d / "k").string() +
                           " >/dev/null 2>&1";
  const int status = std::system(kill.c_str());
  const bool killed = WIFEXITED(status) && WEXITSTATUS(status) == 137;
  std::printf("SIGKILL after %.2f s: %s\n", 0.4 * straight, killed ? "killed" : "it had finished");
  if (killed) {
    EXPECT_FALSE(fs::exists(d / "k"));
    EXPECT_TRUE(fs::exists(d / "k.partial" / "checkpoints" / "test.ckpt"));
  }
  r = run_cli(base + (d / "k").string() + " --resume", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  for (const char* f : {"curve.csv", "report.json", "curve.png"}) {
    EXPECT_EQ(slurp(d / "a" / f), slurp(d / "b" / f)) << f << " after SIGTERM and --resume";
    EXPECT_EQ(slurp(d / "a" / f), slurp(d / "k" / f)) << f << " after SIGKILL and --resume";
  }
  EXPECT_FALSE(fs::exists(d / "b.partial"));
  EXPECT_FALSE(fs::exists(d / "k.partial"));
}
