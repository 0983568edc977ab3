// Smooth links (AdaptiveParams::smooth_links): links that would turn back on a pass are
// flown as loops over the cleared floor. Judged by the independent sweep: reversals (the
// floor pass turning by more than 135 degrees within 1 mm), gouge, residual and band.
#include <gtest/gtest.h>

#include "pocket/adaptive_test_util.h"

namespace swarf {
namespace {

// The L's passes for a ø8 at 20 %, climb, one way or both, straight or smooth links.
testing::SweptPath run(const Pocket& p, bool one_way, bool smooth_links) {
  return testing::generate_swept(p, 8.0, 1.6, {.one_way = one_way, .smooth_links = smooth_links});
}

// Safe as the straight links are: no gouge, no more material left, no slot.
void expect_as_clean(const testing::SweptPath& smooth, const testing::SweptPath& straight) {
  EXPECT_LE(smooth.sweep.max_gouge_mm, 1e-6);
  EXPECT_LE(smooth.sweep.residual_mm2, straight.sweep.residual_mm2 + 0.05);
  EXPECT_EQ(smooth.sweep.slot_length_mm, 0.0);
}

double reversals_per_mm(const testing::SweptPath& o) {
  return o.sweep.reversals / o.sweep.floor_length_mm;
}

// The L with islands at 0.6 scale (ø8 at 20 %), both ways: most hooks where a pass ends at
// a wall and the next comes back are loops now. Measured: reversals per metre 82.9 -> 44.8,
// within +-20 % 86.1 -> 86.8 %, machining 93 -> 96 s (the loops' length at the link feed).
TEST(AdaptiveSmoothLinks, FewerReversalsAndTheCutUnchanged) {
  const Pocket l = testing::scaled(testing::load_test_pocket("l_pocket_islands.json"), 0.6);
  const testing::SweptPath straight = run(l, false, false);
  const testing::SweptPath smooth = run(l, false, true);
  expect_as_clean(smooth, straight);
  EXPECT_LT(reversals_per_mm(smooth), 0.7 * reversals_per_mm(straight));
  // The loops cut nothing: the cut and its engagement stay what they were.
  EXPECT_GE(smooth.sweep.within_20pct, straight.sweep.within_20pct - 0.01);
  EXPECT_LE(smooth.metrics.machining_time_s, 1.1 * straight.metrics.machining_time_s);
  EXPECT_GT(smooth.metrics.air_length_mm, straight.metrics.air_length_mm);
}

// One way, every pass ends against a wall and the next starts back along the front. The
// loops take out fewer of the turns there (60.6 -> 51.7 per metre; most likely because a
// pass that ran into a wall must leave it with a corner, and a loop after a corner needs
// more room than the floor near the wall has; not proven). The loops stay safe and the
// passes climb.
TEST(AdaptiveSmoothLinks, OneWayTurnsBackLessAndStaysClimbAndClean) {
  const Pocket l = testing::scaled(testing::load_test_pocket("l_pocket_islands.json"), 0.6);
  const testing::SweptPath straight = run(l, true, false);
  const testing::SweptPath smooth = run(l, true, true);
  expect_as_clean(smooth, straight);
  EXPECT_GE(smooth.sweep.climb_share, 0.95);
  EXPECT_LT(reversals_per_mm(smooth), 0.95 * reversals_per_mm(straight));
}

// A rectangle with a rectangular island, ø8 at 15 %, with smooth links: two moves round
// the island's corner ran between points on the tool's exact offset 0.3 mm apart, and the
// chord sagged 2.8 um towards the corner, 0.8 um into the island past the 2 um the passes
// keep off it: the re-simulation counted two gouging steps (the output, as swept, was
// clear). keep_chords_off_walls (wall_reach.cpp) now splits such moves on the path itself.
TEST(AdaptiveSmoothLinks, NoMoveRoundAnIslandsCornerCutsIntoIt) {
  const Pocket p =
      make_pocket({{0, 0}, {40, 0}, {40, 30}, {0, 30}}, {{{14, 10}, {22, 10}, {22, 16}, {14, 16}}},
                  "rectangle with an island")
          .value();
  AdaptiveParams ap = testing::params_3mm_deep(1.2);
  ap.smooth_links = true;
  auto r = adaptive_pocket(p, testing::flat_mill(8.0), ap);
  ASSERT_TRUE(r.ok()) << r.status().to_string();
  EXPECT_EQ(r->gouge_steps, 0);
  const testing::SweptPath s = testing::swept(p, 8.0, *r);
  EXPECT_LE(s.sweep.max_gouge_mm, 1e-6);
}

}  // namespace
}  // namespace swarf
