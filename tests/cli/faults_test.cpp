// Faults: a damaged record of an interrupted run is refused by its checksum and redone, saying
// so, never used silently.
#include "cli_helpers.h"

#include "../sanitized.h"

#include <gtest/gtest.h>

#include <string>

namespace fs = std::filesystem;
using namespace cli_test;

// A library particle record with one changed byte, left in DIR.partial by an interrupted run, is
// redone (one warning line naming it) and the library ends byte-identical to a clean run.
namespace {

// The tiny rock library built twice in d: clean/ and lib.partial/ (a finished run renamed to
// stand for what a killed one leaves). Returns the command, less its output directory.
std::string clean_and_partial_library(const fs::path& d) {
  write(d / "rocks.toml", kTinyRocks);
  const std::string run = "library --quiet --recipe " + (d / "rocks.toml").string() + " --out ";
  for (const char* out : {"clean", "lib"}) {
    const Result r = run_cli(run + (d / out).string(), d);
    EXPECT_EQ(r.rc, 0) << r.err;
  }
  fs::rename(d / "lib", d / "lib.partial");
  return run;
}

// Starts `clumpkit specimen` on `recipe` into `out` and sends it SIGTERM as soon as the stage
// record `record` exists (or after a minute).
void stop_at_first_stage_record(const fs::path& recipe, const fs::path& out,
                                const fs::path& record) {
  const std::string start = std::string(CLUMPKIT_BINARY) + " specimen --quiet --recipe " +
                            recipe.string() + " --out " + out.string();
  const std::string script =
      "(" + start + " >/dev/null 2>&1 & pid=$!; for i in $(seq 6000); do [ -e " + record.string() +
      " ] && break; sleep 0.01; done; kill -TERM $pid; wait $pid)";
  std::system(("bash -c '" + script + "'").c_str());
}

}  // namespace

TEST(CliFaults, LibraryRedoesAParticleRecordThatFailsItsChecksum) {
  const fs::path d = scratch();
  const std::string run = clean_and_partial_library(d);
  const fs::path rec = d / "lib.partial" / "particles" / "00002.json";
  std::string text = slurp(rec);
  const std::size_t at = text.find("\"volume\": ") + 11;  // a digit of a descriptor
  ASSERT_NE(at, std::string::npos + 11);
  text[at] = text[at] == '1' ? '2' : '1';
  write(rec, text);
  const Result r = run_cli(run + (d / "lib").string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.err.find("particles/00002.json was damaged (checksum): particle redone"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("(5 kept from an earlier run)"), std::string::npos) << r.out;
  for (const char* f : {"library.csv", "particles/00002.json", "particles/00002.csv"})
    EXPECT_EQ(slurp(d / "lib" / f), slurp(d / "clean" / f)) << f;
}

// A run killed mid-write leaves a half-written temporary beside its target (".NAME.tmp-PID-N");
// the resumed library removes them, so the published directory holds exactly a clean run's
// files. (Found as a rare failure of Cli.LibraryDeterministicAndResumable under load.)
TEST(CliFaults, LibraryResumeDropsHalfWrittenTemporaries) {
  const fs::path d = scratch();
  const std::string run = clean_and_partial_library(d);
  fs::remove(d / "lib.partial" / "library.csv");
  fs::remove(d / "lib.partial" / "particles" / "00003.json");
  write(d / "lib.partial" / "particles" / ".00003.json.tmp-4242-7", "{\"id\": 3, \"fra");
  write(d / "lib.partial" / ".library.csv.tmp-4242-9", "id,fraction\n0,");
  const Result r = run_cli(run + (d / "lib").string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  std::size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(d / "lib")) {
    if (!e.is_regular_file()) continue;
    ++files;
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
    const fs::path rel = fs::relative(e.path(), d / "lib");
    EXPECT_EQ(slurp(e.path()), slurp(d / "clean" / rel)) << rel;
  }
  std::size_t clean = 0;
  for (const auto& e : fs::recursive_directory_iterator(d / "clean")) clean += e.is_regular_file();
  EXPECT_EQ(files, clean);
}

// A specimen stage record with one changed byte is refused on --resume, naming the file; the
// run is stopped by SIGTERM as soon as that record exists.
TEST(CliFaults, SpecimenRefusesAStageRecordThatFailsItsChecksum) {
  const fs::path d = scratch();
  const fs::path recipe = tiny_specimen_recipe(d);
  const fs::path out = d / "spec",
                 record = d / "spec.partial" / "checkpoints" / "calibration-0.done";
  stop_at_first_stage_record(recipe, out, record);
  ASSERT_TRUE(fs::exists(record)) << "the run ended before its first stage record";
  ASSERT_FALSE(fs::exists(out));
  std::string text = slurp(record);
  const std::size_t digit = text.find_first_of("0123456789");
  ASSERT_NE(digit, std::string::npos);
  text[digit] = text[digit] == '1' ? '2' : '1';
  write(record, text);
  const Result r = run_cli(
      "specimen --quiet --resume --recipe " + recipe.string() + " --out " + out.string(), d);
  expect_one_line_error(r, "calibration-0.done: stage record checksum mismatch");
  EXPECT_FALSE(fs::exists(out));
}

// SIGTERM once the first stage is recorded, then --resume: the same bytes as a run never
// stopped (the shared tiny specimen). The short sibling, for the sanitizer pass, of
// Cli.SpecimenSameForAnyThreadCountAndAfterAKill (label long).
TEST(CliFaults, SpecimenStoppedAfterItsFirstStageResumesToTheSameBytes) {
  const fs::path d = scratch();
  const fs::path recipe = tiny_specimen_recipe(d);
  // Under the sanitizers (where a tiny build takes a minute) the tiny recipe in a 40 × 84 mm
  // container instead of 60 × 100 mm: 200 bodies instead of 572 through the same stages (six
  // calibrations, two layers, four correction rounds) in a quarter of the time, compared with a
  // clean build of its own (two small builds against one tiny: ~1.9x less work). Its calibration
  // packs stay above the 30 mm that the measurement margins need (those of a 40 × 70 mm container
  // fall short). The Release pass stops and resumes the tiny specimen itself.
  if (kSanitized) {
    std::string smaller = kTinySpecimen;
    smaller.replace(smaller.find("diameter = 0.060"), 16, "diameter = 0.040");
    smaller.replace(smaller.find("height = 0.100"), 14, "height = 0.084");
    write(recipe, smaller);
  }
  const fs::path out = d / "spec",
                 record = d / "spec.partial" / "checkpoints" / "calibration-0.done";
  stop_at_first_stage_record(recipe, out, record);
  ASSERT_TRUE(fs::exists(record)) << "the run ended before its first stage record";
  ASSERT_FALSE(fs::exists(out));
  const Result r = run_cli(
      "specimen --quiet --resume --recipe " + recipe.string() + " --out " + out.string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  if (kSanitized) {
    const Result clean = run_cli(
        "specimen --quiet --recipe " + recipe.string() + " --out " + (d / "whole").string(), d);
    ASSERT_EQ(clean.rc, 0) << clean.err;
  }
  const fs::path whole = kSanitized ? d / "whole" : shared_tiny_specimen();
  for (const char* f : {"specimen.csv", "calibration.csv"})
    EXPECT_EQ(slurp(out / f), slurp(whole / f)) << f;
}

// A library stopped by SIGTERM at a random time, then run again with the same command, ends
// byte-identical to a run never stopped (twice, at times drawn afresh on every test run).
TEST(CliFaults, LibraryStoppedAtRandomTimesEndsByteIdentical) {
  const fs::path d = scratch();
  std::string recipe = kTinyRocks;
  recipe.replace(recipe.find("count = 6"), 9, "count = 60");
  write(d / "rocks.toml", recipe);
  // Every run writes to the same --out (an output may name its directory), then is moved aside.
  const std::string out = (d / "lib").string();
  const std::string run =
      "library --quiet --recipe " + (d / "rocks.toml").string() + " --out " + out;
  Result r;
  const double whole = timed([&] { r = run_cli(run, d); });
  ASSERT_EQ(r.rc, 0) << r.err;
  fs::rename(out, d / "clean");
  for (int k = 0; k < 2; ++k) {
    const double when = random_seconds(0.05 * whole, 0.95 * whole);
    const int rc = run_cli_stopped_after(run, d, when);
    std::printf("library of %.2f s stopped by SIGTERM after %.3f s: exit %d\n", whole, when, rc);
    // 130: stopped at a safe point; 0: it had finished; 143: the signal came before the job
    // installed its handler (a loaded machine can take that long to start the process), and
    // killed it.
    EXPECT_TRUE(rc == 130 || rc == 0 || rc == 143) << slurp(d / "stopped.err");
    if (rc != 0) {
      EXPECT_FALSE(fs::exists(out));
    }
    r = run_cli(run, d);
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_FALSE(fs::exists(out + ".partial"));
    const fs::path at = d / ("stopped-" + std::to_string(k));
    fs::rename(out, at);
    expect_same_outputs(d / "clean", at);
  }
}

// A file-size limit hit mid-write (ulimit -f; clumpkit ignores SIGXFSZ so the write error
// surfaces) gives exit 2 and one line naming the file, and leaves the earlier output intact with
// no temporary file beside it.
TEST(CliFaults, FileSizeLimitMidWriteKeepsTheEarlierOutput) {
  const fs::path d = scratch();
  const std::string shape = "shape ellipsoid --axes 3,2,1 --level 5 -o ";
  Result r = run_cli(shape + (d / "big.stl").string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  ASSERT_GT(fs::file_size(d / "big.stl"), 200000u);
  write(d / "out.stl", "earlier output\n");
  const std::string limited = "ulimit -f 64; exec " + std::string(CLUMPKIT_BINARY) + " " + shape +
                              (d / "out.stl").string() + " 2>" + (d / "err.txt").string();
  const int status = std::system(("bash -c '" + limited + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal: SIGXFSZ not ignored";
  Result limit;
  limit.rc = WEXITSTATUS(status);
  limit.err = slurp(d / "err.txt");
  expect_one_line_error(limit, "out.stl: write failed: File too large");
  EXPECT_EQ(slurp(d / "out.stl"), "earlier output\n");
  for (const auto& e : fs::directory_iterator(d))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}
