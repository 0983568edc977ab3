// One-way passes (AdaptiveParams::one_way): every pass in the milling direction asked for,
// judged by the independent sweep's reading of which side of the motion the material is on.
#include <gtest/gtest.h>

#include "pocket/adaptive_test_util.h"

namespace swarf {
namespace {

// The L's passes for a ø8 at 20 %, climb or conventional, one way or both.
testing::SweptPath run(const Pocket& p, bool climb, bool one_way) {
  return testing::generate_swept(p, 8.0, 1.6, {.climb = climb, .one_way = one_way});
}

void expect_clean(const testing::SweptPath& o) {
  EXPECT_LE(o.sweep.max_gouge_mm, 1e-6);
  EXPECT_LE(o.sweep.residual_mm2, 0.5);
  EXPECT_EQ(o.sweep.slot_length_mm, 0.0);
}

// Both ways (seed 000), a pass that ends against a wall comes straight back with the
// material on its other side: on this L about a third of the one-sided cut is conventional.
// One way, each such pass ends and the next starts where the front beside it begins:
// 97.6 % climb, 60.6 reversals per metre against 82.9, within +-20 % 82.7 % against 86.1 %.
TEST(AdaptiveOneWay, EveryPassClimbsAndTheCutStaysInTheBand) {
  const Pocket l = testing::scaled(testing::load_test_pocket("l_pocket_islands.json"), 0.6);
  const testing::SweptPath both = run(l, true, false);
  const testing::SweptPath one = run(l, true, true);
  expect_clean(one);
  EXPECT_GE(one.sweep.climb_share, 0.95);
  EXPECT_GT(one.sweep.climb_share, both.sweep.climb_share + 0.1);
  // Fewer places where the floor pass turns back: the passes that came back are links now,
  // but a link starts only where a pass has run the front's length.
  EXPECT_LT(one.sweep.reversals / one.sweep.floor_length_mm,
            both.sweep.reversals / both.sweep.floor_length_mm);
  // What it reaches today (both ways: 86 %); the pass starts cost a few points.
  EXPECT_GE(one.sweep.within_20pct, 0.80);
}

// The same rule with the mirrored frame: every pass conventional.
TEST(AdaptiveOneWay, ConventionalOneWayKeepsTheMaterialOnTheLeft) {
  const Pocket l = testing::scaled(testing::load_test_pocket("l_pocket_islands.json"), 0.6);
  const testing::SweptPath one = run(l, false, true);
  expect_clean(one);
  EXPECT_LE(one.sweep.climb_share, 0.05);
}

}  // namespace
}  // namespace swarf
