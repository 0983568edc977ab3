// The feeds of the entries: helices and ramps (and the helix's full turn at depth) at the
// ramp feed, the cutting feed unless set; straight plunges at the plunge feed. Checked on
// the program's own moves and on its machining time.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "pocket/adaptive_test_util.h"
#include "swarf/pocket/adaptive.h"
#include "swarf/pocket/contour_parallel.h"
#include "swarf/toolpath/metrics.h"

namespace swarf {
namespace {

// Indices of the entry moves: each run of helix or ramp moves and, after a helix, the arcs
// at depth that close it (the full turn that clears the hole's floor).
std::vector<std::size_t> entry_moves(const std::vector<Move>& mv) {
  std::vector<std::size_t> out;
  bool after_helix = false;
  for (std::size_t k = 0; k < mv.size(); ++k) {
    const bool entry = mv[k].kind == MoveKind::kHelix || mv[k].kind == MoveKind::kRamp ||
                       (after_helix && mv[k].kind == MoveKind::kArc);
    if (entry) out.push_back(k);
    after_helix = entry && (mv[k].kind == MoveKind::kHelix || after_helix);
  }
  return out;
}

struct Case {
  std::string name;
  Pocket pocket;
  double tool_d;
};

std::vector<Case> cases() {
  return {
      {"L (helix)", testing::scaled(testing::load_test_pocket("l_pocket_islands.json"), 0.6), 8.0},
      {"channel (ramp)",
       make_pocket({{0, 0}, {40, 0}, {40, 8.8}, {0, 8.8}}, {}, "channel 8.8 x 40").value(), 8.0},
      // Two chambers joined by a neck a tenth wider than the ø10: plunged through.
      {"dumbbell (neck plunges)", testing::dumbbell_pocket(), 10.0},
  };
}

TEST(AdaptiveEntryFeed, HelicesAndRampsAtTheRampFeedPlungesAtThePlungeFeed) {
  for (const Case& c : cases()) {
    AdaptiveParams ap;
    ap.stepover_mm = 0.2 * c.tool_d;
    ap.depth_mm = 6.0;
    ap.stepdown_mm = 3.0;
    auto fast = adaptive_pocket(c.pocket, testing::flat_mill(c.tool_d), ap);
    ASSERT_TRUE(fast.ok()) << c.name << ": " << fast.status().to_string();
    const std::vector<Move>& mv = fast->toolpath.moves;
    const std::vector<std::size_t> entries = entry_moves(mv);
    ASSERT_FALSE(entries.empty()) << c.name;
    for (std::size_t k : entries)  // the default: the cutting feed
      EXPECT_EQ(mv[k].feed_mm_min, ap.feed_mm_min) << c.name << " move " << k;
    int plunges = 0;
    for (const Move& m : mv)
      if (m.kind == MoveKind::kPlunge) {
        EXPECT_EQ(m.feed_mm_min, ap.plunge_feed_mm_min) << c.name;
        plunges += m.cutting ? 1 : 0;
      }
    if (c.tool_d == 10.0) {
      EXPECT_GT(plunges, 0) << c.name;  // the neck's
    }

    // A ramp feed of its own changes those moves' feed and nothing else, and the machining
    // time by their length at the two feeds.
    ap.ramp_feed_mm_min = 450.0;
    auto slow = adaptive_pocket(c.pocket, testing::flat_mill(c.tool_d), ap);
    ASSERT_TRUE(slow.ok()) << c.name;
    const std::vector<Move>& sv = slow->toolpath.moves;
    ASSERT_EQ(sv.size(), mv.size()) << c.name;
    double entry_mm = 0.0;
    std::size_t e = 0;
    for (std::size_t k = 0; k < mv.size(); ++k) {
      EXPECT_EQ(sv[k].end, mv[k].end) << c.name << " move " << k;
      EXPECT_EQ(sv[k].kind, mv[k].kind) << c.name << " move " << k;
      if (e < entries.size() && entries[e] == k) {
        EXPECT_EQ(sv[k].feed_mm_min, 450.0) << c.name << " move " << k;
        entry_mm += move_length(mv[k - 1].end, mv[k]);
        ++e;
      } else {
        EXPECT_EQ(sv[k].feed_mm_min, mv[k].feed_mm_min) << c.name << " move " << k;
      }
    }
    const double dt = compute_metrics(slow->toolpath).machining_time_s -
                      compute_metrics(fast->toolpath).machining_time_s;
    EXPECT_NEAR(dt, entry_mm * 60.0 * (1.0 / 450.0 - 1.0 / ap.feed_mm_min), 1e-6) << c.name;
    EXPECT_GT(entry_mm, 50.0) << c.name;  // two layers of 3 mm at 3 degrees
  }
}

TEST(AdaptiveEntryFeed, ANegativeRampFeedIsABadParameter) {
  AdaptiveParams ap;
  ap.ramp_feed_mm_min = -1.0;
  auto r = adaptive_pocket(cases()[1].pocket, testing::flat_mill(8.0), ap);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), Error::kBadParameter);
  EXPECT_NE(r.status().message().find("ramp_feed_mm_min"), std::string::npos);
}

// The contour-parallel baseline's helices the same way.
TEST(AdaptiveEntryFeed, TheContourBaselinesHelicesAtTheRampFeed) {
  const Pocket p = testing::scaled(testing::load_test_pocket("l_pocket_islands.json"), 0.6);
  ContourParallelParams cp;
  cp.stepover_mm = 1.6;
  for (double ramp_feed : {0.0, 450.0}) {
    cp.ramp_feed_mm_min = ramp_feed;
    auto r = contour_parallel_pocket(p, testing::flat_mill(8.0), cp);
    ASSERT_TRUE(r.ok()) << r.status().to_string();
    int arcs = 0;
    for (const Move& m : r->toolpath.moves)
      if (m.is_arc()) {
        ++arcs;
        EXPECT_EQ(m.feed_mm_min, ramp_feed > 0.0 ? ramp_feed : cp.feed_mm_min);
      }
    EXPECT_GT(arcs, 4);
  }
}

}  // namespace
}  // namespace swarf
