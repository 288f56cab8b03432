// The readers' plumbing (io/base): the whole-file reader, CSV cells, numbers that must fill their
// token, little-endian bytes.
#include "io/base/text.h"
#include "io/base/little_endian.h"

#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

using namespace clumpkit;
namespace fs = std::filesystem;

TEST(Text, ReadFileGivesEveryByteOrNamesTheFile) {
  const fs::path dir = fs::path(::testing::TempDir()) / "clumpkit_text_test";
  fs::create_directories(dir);
  const std::string bytes("a\0b\r\n\xff", 6);
  std::ofstream(dir / "f.bin", std::ios::binary) << bytes;
  EXPECT_EQ(read_file((dir / "f.bin").string()), bytes);
  std::ofstream(dir / "empty.txt").close();
  EXPECT_EQ(read_file((dir / "empty.txt").string()), "");
  try {
    read_file((dir / "missing.txt").string(), "recipe file");
    FAIL() << "no error for a missing file";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "missing.txt").string() + ": file not found");
  }
  try {
    read_file(dir.string(), "recipe file");
    FAIL() << "no error for a directory";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), dir.string() + ": is a directory, not a recipe file");
  }
  fs::remove_all(dir);
}

TEST(Text, SplitCsvKeepsEmptyCellsButNoTrailingOne) {
  EXPECT_EQ(split_csv("a,b,,c"), (std::vector<std::string>{"a", "b", "", "c"}));
  EXPECT_EQ(split_csv("1.5"), (std::vector<std::string>{"1.5"}));
  EXPECT_EQ(split_csv("x,"), (std::vector<std::string>{"x"}));
  EXPECT_TRUE(split_csv("").empty());
}

TEST(Text, NumbersMustFillTheirToken) {
  EXPECT_EQ(to_number("1.5"), 1.5);
  EXPECT_EQ(to_number("+2e-3"), 2e-3);
  EXPECT_EQ(to_number("-0.25"), -0.25);
  // Round trip: the shortest form of a double reads back to the same bits.
  EXPECT_EQ(to_number("0.1"), 0.1);
  EXPECT_EQ(to_number("2.2250738585072014e-308"), std::numeric_limits<double>::min());
  EXPECT_TRUE(std::isinf(*to_number("inf")));  // the caller checks finiteness
  for (const char* bad : {"", " 1", "1 ", "1,5", "1.5x", "+-1", "0x10", "--1", "e5", "1e999"})
    EXPECT_FALSE(to_number(bad).has_value()) << "'" << bad << "'";
  EXPECT_EQ(to_integer("42"), 42);
  EXPECT_EQ(to_integer("+7"), 7);
  EXPECT_EQ(to_integer("-3"), -3);
  for (const char* bad : {"", "1.0", "4e2", "12a", "99999999999999999999"})
    EXPECT_FALSE(to_integer(bad).has_value()) << "'" << bad << "'";
}

TEST(LittleEndian, StoresLowByteFirstAndRoundTrips) {
  std::string b;
  append_le<std::uint32_t>(b, 0x04030201u);
  append_le<double>(b, -1.25);
  ASSERT_EQ(b.size(), 12u);
  EXPECT_EQ(b.substr(0, 4), std::string("\x01\x02\x03\x04", 4));
  // -1.25 = 0xBFF4000000000000: its bytes low first.
  EXPECT_EQ(b.substr(4), std::string("\x00\x00\x00\x00\x00\x00\xf4\xbf", 8));
  EXPECT_EQ(load_le<std::uint32_t>(b.data()), 0x04030201u);
  EXPECT_EQ(load_le<double>(b.data() + 4), -1.25);
  char f[4];
  store_le<float>(f, 3.5f);
  EXPECT_EQ(load_le<float>(f), 3.5f);
}
