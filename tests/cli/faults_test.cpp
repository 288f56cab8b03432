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
