// The number formatter: exact round trips for files, rounded values for views.
#include "geom/format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>

using namespace clumpkit;

TEST(Format, NumbersReadBackExactly) {
  for (double v : {0.1, 1.0 / 3.0, 2.0 / 3.0 * 1e-300, 6.02214076e23, -0.0, 123456789.0})
    EXPECT_EQ(std::strtod(format_number(v).c_str(), nullptr), v) << format_number(v);
}

TEST(Format, RoundSignificantKeepsThatManyDigits) {
  EXPECT_EQ(round_significant(0.123456789, 6), 0.123457);
  EXPECT_EQ(round_significant(-98765432.1, 3), -98800000.0);
  EXPECT_EQ(round_significant(2.5e-7, 6), 2.5e-7);
  EXPECT_EQ(round_significant(0.0, 6), 0.0);
  EXPECT_TRUE(std::isnan(round_significant(std::nan(""), 6)));
  EXPECT_EQ(round_significant(std::numeric_limits<double>::infinity(), 6),
            std::numeric_limits<double>::infinity());
  // Rounding is idempotent: a rounded value rounds to itself.
  const double r = round_significant(M_PI, 6);
  EXPECT_EQ(round_significant(r, 6), r);
  EXPECT_NEAR(r, M_PI, 5e-6);
}
