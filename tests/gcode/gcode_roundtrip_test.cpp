// Write then read back: every dialect must give back the moves it was given.
#include <gtest/gtest.h>

#include <random>

#include "gcode/gcode_test_util.h"
#include "swarf/gcode/gcode.h"

namespace swarf {
namespace {

using testing::expect_same_moves;
using testing::kAllDialects;

TEST(GcodeRoundTrip, SamplePathInEveryDialect) {
  const Toolpath p = testing::sample_path();
  for (Dialect d : kAllDialects) {
    for (bool numbers : {false, true}) {
      SCOPED_TRACE(std::string(dialect_name(d)) + (numbers ? " with N-words" : ""));
      GcodeOptions o;
      o.dialect = d;
      o.line_numbers = numbers;
      const std::string g = write_gcode(p, o);
      const auto read = parse_gcode(g, "sample.nc");
      ASSERT_TRUE(read.ok()) << read.status().message() << "\n" << g;
      expect_same_moves(p, *read, d, 1e-4);
      EXPECT_EQ(read->tool_number, d == Dialect::kGrbl ? 1 : 3);  // grbl: comment only
      EXPECT_EQ(read->spindle_rpm, 12000.0);
      EXPECT_EQ(read->coolant, Coolant::kFlood);
    }
  }
}

TEST(GcodeRoundTrip, RandomPathsAtSeveralPrecisions) {
  std::mt19937 rng(20261121);
  for (int trial = 0; trial < 30; ++trial) {
    const Toolpath p = testing::random_path(rng, 40);
    for (Dialect d : kAllDialects) {
      for (int decimals : {3, 4, 6}) {
        SCOPED_TRACE("trial " + std::to_string(trial) + " " + std::string(dialect_name(d)) +
                     " decimals " + std::to_string(decimals));
        GcodeOptions o;
        o.dialect = d;
        o.decimals = decimals;
        const auto read = parse_gcode(write_gcode(p, o), "random.nc");
        ASSERT_TRUE(read.ok()) << read.status().message();
        expect_same_moves(p, *read, d, std::pow(10.0, -decimals));
        if (::testing::Test::HasFailure()) return;
      }
    }
  }
}

}  // namespace
}  // namespace swarf
