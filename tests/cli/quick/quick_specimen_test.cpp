// The bundled quick specimen (assets/recipes/quick-specimen.toml) end to end: its target
// relative density, and SIGTERM at two random times (the second during a resume) then --resume
// giving the same bytes. About 85 s a run on Release; labelled `quick` in ctest, and left out of
// the sanitizer pass, where the tiny specimen runs the same stages (a quick run takes 14 minutes
// under ASan + UBSan).
#include "../cli_helpers.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>

namespace fs = std::filesystem;
using namespace cli_test;

TEST(CliQuick, QuickSpecimenReachesItsTargetAndResumesByteIdenticalAfterSigterm) {
  const fs::path d = scratch();
  // Every run writes to the same --out (report.json names it), then is moved aside.
  const std::string out = (d / "q").string();
  const std::string run = "specimen --quiet --recipe " + std::string(CLUMPKIT_SOURCE_DIR) +
                          "/assets/recipes/quick-specimen.toml --out " + out;
  Result r;
  const double whole = timed([&] { r = run_cli(run + " --json", d); });
  ASSERT_EQ(r.rc, 0) << r.err;
  fs::rename(out, d / "clean");
  const auto report = nlohmann::json::parse(r.out);
  std::printf("quick specimen: porosity %.4f, Dr %.3f, mu* %.3f, %.0f s\n",
              report["porosity"].get<double>(), report["relative_density"].get<double>(),
              report["friction_compaction"].get<double>(),
              report["seconds"]["total"].get<double>());
  EXPECT_NEAR(report["relative_density"].get<double>(), 0.5, 0.03);
  double lo = 1, hi = 0;
  for (double n : report["layer_porosity"]) lo = std::min(lo, n), hi = std::max(hi, n);
  EXPECT_LE(hi - lo, 0.02);
  // About the container height (0.2 m): the layer volumes follow the target porosity.
  EXPECT_NEAR(report["height"].get<double>(), 0.2, 0.03);

  // Stopped at a time drawn afresh on every test run, resumed and stopped again at another,
  // then resumed to the end: the same bytes as the run never stopped (report.json's wall-clock
  // seconds aside). One chain covers two stops (and a resume that is itself stopped) for the
  // cost of one run.
  std::string args = run;
  for (int k = 0; k < 2; ++k) {
    const double when = random_seconds(0.02 * whole, 0.49 * whole);
    const int rc = run_cli_stopped_after(args, d, when);
    std::printf("quick specimen of %.0f s, stop %d by SIGTERM after %.1f s: exit %d\n", whole,
                k + 1, when, rc);
    // 130: stopped at a safe point; 0: it had finished; 143: the signal came before the job
    // installed its handler (a loaded machine can take that long to start the process), and
    // killed it.
    EXPECT_TRUE(rc == 130 || rc == 0 || rc == 143) << slurp(d / "stopped.err");
    if (rc == 130) {
      EXPECT_NE(slurp(d / "stopped.err").find("continue with --resume"), std::string::npos)
          << slurp(d / "stopped.err");
    }
    if (rc == 0) break;
    EXPECT_FALSE(fs::exists(out));
    args = run + " --resume";
  }
  if (!fs::exists(out)) {
    r = run_cli(run + " --resume", d);
    ASSERT_EQ(r.rc, 0) << r.err;
  }
  EXPECT_FALSE(fs::exists(out + ".partial"));
  fs::rename(out, d / "stopped");
  expect_same_outputs(d / "clean", d / "stopped");
}
