// Faults: a damaged record of an interrupted run is refused by its checksum and redone, saying
// so, never used silently.
#include "cli_helpers.h"

#include <gtest/gtest.h>

#include <string>

namespace fs = std::filesystem;
using namespace cli_test;

// A library particle record with one changed byte, left in DIR.partial by an interrupted run, is
// redone (one warning line naming it) and the library ends byte-identical to a clean run.
TEST(CliFaults, LibraryRedoesAParticleRecordThatFailsItsChecksum) {
  const fs::path d = scratch();
  write(d / "rocks.toml", kTinyRocks);
  const std::string run = "library --quiet --recipe " + (d / "rocks.toml").string() + " --out ";
  Result r = run_cli(run + (d / "clean").string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  r = run_cli(run + (d / "lib").string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  // What a killed run leaves: the finished particles in lib.partial.
  fs::rename(d / "lib", d / "lib.partial");
  const fs::path rec = d / "lib.partial" / "particles" / "00002.json";
  std::string text = slurp(rec);
  const std::size_t at = text.find("\"volume\": ") + 11;  // a digit of a descriptor
  ASSERT_NE(at, std::string::npos + 11);
  text[at] = text[at] == '1' ? '2' : '1';
  write(rec, text);
  r = run_cli(run + (d / "lib").string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.err.find("particles/00002.json was damaged (checksum): particle redone"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("(5 kept from an earlier run)"), std::string::npos) << r.out;
  for (const char* f : {"library.csv", "particles/00002.json", "particles/00002.csv"})
    EXPECT_EQ(slurp(d / "lib" / f), slurp(d / "clean" / f)) << f;
}

// A specimen stage record with one changed byte is refused on --resume, naming the file; the
// run is stopped by SIGTERM as soon as that record exists.
TEST(CliFaults, SpecimenRefusesAStageRecordThatFailsItsChecksum) {
  const fs::path d = scratch();
  const fs::path recipe = tiny_specimen_recipe(d);
  const fs::path out = d / "spec",
                 record = d / "spec.partial" / "checkpoints" / "calibration-0.done";
  const std::string start = std::string(CLUMPKIT_BINARY) + " specimen --quiet --recipe " +
                            recipe.string() + " --out " + out.string();
  const std::string script =
      "(" + start + " >/dev/null 2>&1 & pid=$!; for i in $(seq 6000); do [ -e " + record.string() +
      " ] && break; sleep 0.01; done; kill -TERM $pid; wait $pid)";
  std::system(("bash -c '" + script + "'").c_str());
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
