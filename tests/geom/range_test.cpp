// The allowed ranges of parameter values: membership at open and closed ends, of integers, and
// the words the recipes and the messages quote.
#include "geom/range.h"

#include "../invalid_input_message.h"
#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace clumpkit;

TEST(Range, EndsAreInOrOutAsTheyAreClosedOrOpen) {
  EXPECT_TRUE(closed(0, 1).contains(0));
  EXPECT_TRUE(closed(0, 1).contains(1));
  EXPECT_TRUE(closed(0, 1).contains(0.5));
  EXPECT_FALSE(closed(0, 1).contains(-1e-300));
  EXPECT_FALSE(closed(0, 1).contains(1.0000001));
  EXPECT_FALSE(open(0.2, 0.9).contains(0.2));
  EXPECT_FALSE(open(0.2, 0.9).contains(0.9));
  EXPECT_TRUE(open(0.2, 0.9).contains(0.37));
  EXPECT_FALSE(open_closed(0, 1).contains(0));
  EXPECT_TRUE(open_closed(0, 1).contains(1));
  EXPECT_TRUE(closed_open(0, 1).contains(0));
  EXPECT_FALSE(closed_open(0, 1).contains(1));
  EXPECT_TRUE(at_least(0).contains(0));
  EXPECT_TRUE(at_least(0).contains(1e300));
  EXPECT_FALSE(at_least(0).contains(-0.1));
  EXPECT_FALSE(above(0).contains(0));
  EXPECT_TRUE(above(0).contains(1e-300));
}

TEST(Range, NanAndInfinityAreInNoRange) {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  for (const Range& r :
       {closed(0, 1), open(0, 1), at_least(0), above(0), integers_from(1), Range{}})
    EXPECT_FALSE(r.contains(nan)) << r.text();
  // An infinite end is open: no range holds an infinity.
  EXPECT_FALSE(at_least(0).contains(inf));
  EXPECT_FALSE(above(0).contains(inf));
  EXPECT_FALSE(integers_from(1).contains(inf));
  EXPECT_FALSE(Range{}.contains(-inf));
  EXPECT_TRUE(Range{}.contains(-1e300));
}

TEST(Range, IntegerRangesHoldWholeNumbersOnly) {
  EXPECT_TRUE(integers(1, 100).contains(1));
  EXPECT_TRUE(integers(1, 100).contains(100));
  EXPECT_FALSE(integers(1, 100).contains(0));
  EXPECT_FALSE(integers(1, 100).contains(101));
  EXPECT_FALSE(integers(1, 100).contains(2.5));
  EXPECT_TRUE(integers_from(1).contains(1e9));
  EXPECT_FALSE(integers_from(1).contains(1.5));
  EXPECT_FALSE(integers_from(1).contains(0));
}

TEST(Range, TextIsWhatTheReferenceAndTheMessagesQuote) {
  EXPECT_EQ(closed_open(0, 1).text(), "[0, 1)");
  EXPECT_EQ(open_closed(0, 1).text(), "(0, 1]");
  EXPECT_EQ(open(0.2, 0.9).text(), "(0.2, 0.9)");
  EXPECT_EQ(closed(1, 1e6).text(), "[1, 1000000]");
  EXPECT_EQ(at_least(0).text(), ">= 0");
  EXPECT_EQ(above(0).text(), "> 0");
  EXPECT_EQ(integers(1, 100).text(), "integer in [1, 100]");
  EXPECT_EQ(integers_from(1).text(), "integer >= 1");
  EXPECT_EQ(Range{}.text(), "any");
}

TEST(Range, OutsideSaysWhyAndRequireThrowsWithNameAndValue) {
  EXPECT_EQ(outside(closed_open(0, 1), 0.5), "");
  EXPECT_EQ(outside(closed_open(0, 1), 1), "must be in [0, 1)");
  EXPECT_EQ(outside(at_least(0), -1), "must be >= 0");
  EXPECT_EQ(outside(integers(1, 100), 2.5), "must be an integer in [1, 100]");
  EXPECT_EQ(outside(integers_from(1), 0), "must be an integer >= 1");
  EXPECT_EQ(invalid_input_message([] { require(open(0.2, 0.9), 0.95, "porosity"); }),
            "porosity: must be in (0.2, 0.9), got 0.95");
  EXPECT_EQ(invalid_input_message([] { require(integers(1, 100), 0, "layers"); }),
            "layers: must be an integer in [1, 100], got 0");
  EXPECT_EQ(invalid_input_message([] { require(above(0), std::nan(""), "kn"); }),
            "kn: must be > 0, got nan");
  EXPECT_EQ(invalid_input_message([] { require(closed(0, 1), 1, "x"); }), "");
  EXPECT_THROW(require(at_least(0), -0.5, "friction"), InvalidInput);
}
