// What the adaptive pocket runs at the link feed (5x the cutting feed by default): links
// over cleared floor and moves that graze, judged by the independent sweep of
// tests/pocket/sweep_checker.cpp per move.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "pocket/adaptive_test_util.h"
#include "pocket/sweep_checker.h"
#include "swarf/pocket/adaptive.h"
#include "swarf/toolpath/metrics.h"

namespace swarf {
namespace {

using testing::flat_mill;
using testing::kCheckerPixel;
using testing::kWallTol;
using testing::params_3mm_deep;
using testing::scaled;

Pocket load(const std::string& name) {
  return testing::load_test_pocket(name);
}

// Keep-tool-down links go over cleared floor at the link feed (the rapid rate by default),
// and they are weighed against a retract as the output makes one (the descent at the plunge
// feed included). The independent sweep checks that what runs at the link feed removes
// nothing but crumbs of its own finer pixels (it may come within a hair of the material).
TEST(AdaptivePocket, LinksOverClearedFloorRunAtTheLinkFeedAndCutNothing) {
  const Pocket p = scaled(load("l_pocket_islands.json"), 0.6);
  const Tool t = flat_mill(6.0);
  AdaptiveParams ap = params_3mm_deep(0.6);
  auto fast = adaptive_pocket(p, t, ap);
  ASSERT_TRUE(fast.ok()) << fast.status().to_string();
  std::vector<testing::SweepSample> samples;
  const auto s = testing::sweep_check(p.region, 3.0, fast->toolpath, fast->target_engagement_deg,
                                      kCheckerPixel, kWallTol, &samples);
  const auto& mv = fast->toolpath.moves;
  double link_len = 0.0, removed = 0.0, all = 0.0;
  std::map<std::size_t, double> per_move;
  for (const auto& q : samples) {
    all += q.removed_mm2;
    const Move& m = mv[q.move];
    if (m.kind != MoveKind::kFeed || m.feed_mm_min != ap.rapid_mm_min) continue;
    link_len += q.length_mm;
    removed += q.removed_mm2;
    per_move[q.move] += q.removed_mm2;
  }
  double most = 0.0;
  for (const auto& [k, a] : per_move)
    most = std::max(most, a);
  std::printf(
      "  links at %.0f mm/min: %.0f mm in %zu moves, removing %.3f mm^2 of %.0f (at most "
      "%.3f mm^2 in one move)\n",
      ap.rapid_mm_min, link_len, per_move.size(), removed, all, most);
  EXPECT_GT(link_len, 100.0);
  // Crumbs of the checker's finer pixels at most (one corner: 0.03 mm^2): under a quarter of
  // what one step at the target removes (stepover x step = 0.18 mm^2).
  EXPECT_LE(removed, 5e-4 * all);
  EXPECT_LE(most, 0.25 * ap.stepover_mm * 0.3);
  EXPECT_LE(s.max_gouge_mm, 1e-6);
  // Links at the cutting feed instead: the path may retract more, and takes longer.
  ap.link_feed_mm_min = ap.feed_mm_min;
  auto slow = adaptive_pocket(p, t, ap);
  ASSERT_TRUE(slow.ok());
  const auto tf = compute_metrics(fast->toolpath), ts = compute_metrics(slow->toolpath);
  std::printf("  machining %.0f s (links at the cutting feed: %.0f s), lifts %zu (%zu)\n",
              tf.machining_time_s, ts.machining_time_s, tf.lift_offs, ts.lift_offs);
  EXPECT_LT(tf.machining_time_s, 0.95 * ts.machining_time_s);
  EXPECT_LE(tf.lift_offs, ts.lift_offs);
}

// A test pocket generated and swept, with what each move at the link feed removes (mm^2)
// and how long it is (mm) by the sweep, per move index.
struct LinkFeedCuts {
  AdaptiveResult result;
  testing::SweepReport sweep;
  std::map<std::size_t, std::pair<double, double>> per_move;
};

LinkFeedCuts link_feed_cuts(const Pocket& p, double tool_d, const AdaptiveParams& ap) {
  LinkFeedCuts out;
  auto r = adaptive_pocket(p, flat_mill(tool_d), ap);
  EXPECT_TRUE(r.ok()) << r.status().to_string();
  if (!r.ok()) return out;
  out.result = std::move(r.value());
  std::vector<testing::SweepSample> samples;
  out.sweep =
      testing::sweep_check(p.region, 0.5 * tool_d, out.result.toolpath,
                           out.result.target_engagement_deg, kCheckerPixel, kWallTol, &samples);
  for (const auto& q : samples) {
    const Move& m = out.result.toolpath.moves[q.move];
    if (m.kind != MoveKind::kFeed || m.feed_mm_min != ap.rapid_mm_min) continue;
    out.per_move[q.move].first += q.removed_mm2;
    out.per_move[q.move].second += q.length_mm;
  }
  return out;
}

LinkFeedCuts link_feed_cuts(const std::string& file, double tool_d, const AdaptiveParams& ap) {
  return link_feed_cuts(load(file), tool_d, ap);
}

// The most a move at the link feed removes per mm of its length (moves of 0.05 mm or more).
double densest_link_feed_cut(const LinkFeedCuts& c) {
  double densest = 0.0;
  for (const auto& [k, v] : c.per_move)
    if (v.second >= 0.05) densest = std::max(densest, v.first / v.second);
  return densest;
}

// Pocket 951 of bench/pocket_random.sh (ø6 at 15 %, a pentagon with a square and a round
// island): five sessions resumed where no straight link from the last cut kept off the
// material and the islands, and each was a retract and a plunge (the raw path has no moves
// to follow there). A way over the cleared floor, searched among the tool centres whose
// disks are clear and pulled taut, keeps the tool down.
TEST(AdaptivePocket, ResumesElsewhereGoOverTheClearedFloorInsteadOfLifting) {
  const AdaptiveParams ap = params_3mm_deep(0.9);
  const LinkFeedCuts c = link_feed_cuts("random_seed951.json", 6.0, ap);
  const auto& s = c.sweep;
  // What runs at the link feed: crumbs of the sweep's finer pixels at most, as in the test
  // above. Two tip visits here ended in a 0.1 mm move at the link feed that took 0.19 and
  // 0.35 mm^2 by the sweep, the pixel model counting none of the material beyond the free
  // pixel centres; the re-simulation counts what the visits reach now.
  double most = 0.0;
  for (const auto& [k, v] : c.per_move)
    most = std::max(most, v.first);
  const auto mt = compute_metrics(c.result.toolpath);
  std::printf("  lifts %zu, at most %.3f mm^2 in one link, machining %.0f s, within20 %.1f %%\n",
              mt.lift_offs, most, mt.machining_time_s, 100 * s.within_20pct);
  EXPECT_EQ(mt.lift_offs, 0U);  // 5 before
  EXPECT_LE(most, 0.25 * ap.stepover_mm * 0.3);
  EXPECT_LE(s.max_gouge_mm, 1e-6);
  EXPECT_LE(s.residual_mm2, 0.5);
  EXPECT_EQ(s.slot_length_mm, 0.0);
  EXPECT_GE(s.within_20pct, 0.89);  // 0.90 before session 49's sweep (0.897 by it)
}

// Pocket 977 of bench/pocket_random.sh (ø3 at 8 %, a polygon with two islands): the search
// for a way over the cleared floor ran on tool centres a sixth of the radius apart, and
// three resumes found none where the clear centres between the islands formed strips
// narrower than that; each lifted for a hop of a few millimetres. Where the coarse search
// finds nothing a finer one (a third of the stride) runs.
TEST(AdaptivePocket, ResumesFindWaysThroughPassagesNarrowerThanTheSearchStride) {
  const AdaptiveParams ap = params_3mm_deep(0.24);
  const LinkFeedCuts c = link_feed_cuts("random_seed977.json", 3.0, ap);
  const auto mt = compute_metrics(c.result.toolpath);
  std::printf("  lifts %zu, machining %.0f s\n", mt.lift_offs, mt.machining_time_s);
  EXPECT_LE(mt.lift_offs, 2U);  // 5 before
  EXPECT_LE(c.sweep.max_gouge_mm, 1e-6);
  EXPECT_LE(c.sweep.residual_mm2, 0.5);
  // The new links go over cleared floor: the most a link-feed move removes is a few of
  // the checker's pixels.
  double most = 0.0;
  for (const auto& [k, v] : c.per_move)
    most = std::max(most, v.first);
  EXPECT_LE(most, 4.0 * kCheckerPixel * kCheckerPixel);
}

// Pocket 955 of bench/pocket_random.sh (ø16 at 10 %, an L with four islands). A move runs at
// the link feed when the re-simulation finds it removing at most 1/25 of a target step (at
// 5x the feed, the chip of a target cut); that allowance is per full step, and short moves
// of a tip visit (0.1 mm) took a pixel or two each at the link feed: 0.57 mm of radial depth
// by the sweep against the 0.064 mm allowed. A shorter move gets its share of the allowance.
// Checked per move by the sweep, removal per mm of path, crumbs of its pixels allowed.
// A random test pocket's densest link-feed move by the sweep: within the graze allowed (a
// 25th of the stepover as radial depth) plus `crumb_px` of the checker's pixels; no gouge.
LinkFeedCuts expect_link_feed_grazes(const std::string& file, double tool_d, double stepover_mm,
                                     double crumb_px) {
  const AdaptiveParams ap = params_3mm_deep(stepover_mm);
  LinkFeedCuts c = link_feed_cuts(file, tool_d, ap);
  const double densest = densest_link_feed_cut(c);
  std::printf("  densest link-feed move: %.3f mm of radial depth\n", densest);
  EXPECT_LE(densest, stepover_mm / 25.0 + crumb_px * kCheckerPixel);
  EXPECT_LE(c.sweep.max_gouge_mm, 1e-6);
  return c;
}

TEST(AdaptivePocket, ShortMovesAtTheLinkFeedGrazeNoMoreThanTheirShare) {
  expect_link_feed_grazes("random_seed955.json", 16.0, 1.6, 2.0);
}

// A rectangle whose corners are rounded 0.2 mm wider than the tool's radius (as a part's
// drawing rounds them for a cutter a size up): the tool centres' region ends in arcs of
// 0.2 mm radius, 12 vertices of 7.5 degrees each, which no single vertex shows as a tip, and
// the free pixel centres stop about half a millimetre short of them. The tool must reach
// each corner (else a crescent of a few mm^2 stays), and at the cutting feed: a scallop dab
// into such a corner took 1.8 mm^2 in a 0.7 mm move at the link feed (part-like pocket
// 2312), the re-simulation counting none of the material beyond the free centres.
TEST(AdaptivePocket, CornersRoundedALittleWiderThanTheToolAreReachedAtTheCuttingFeed) {
  const double width = 120.0, height = 55.0, radius = 10.0, rc = radius + 0.2;
  Ring outer;
  const Vec2 centres[4] = {
      {width - rc, rc}, {width - rc, height - rc}, {rc, height - rc}, {rc, rc}};
  for (int c = 0; c < 4; ++c) {
    for (int k = 0; k <= 12; ++k) {
      const double a = deg_to_rad(-90.0 + 90.0 * c + 7.5 * k);
      outer.push_back(centres[c] + Vec2{std::cos(a), std::sin(a)} * rc);
    }
  }
  const Pocket p = make_pocket(outer, {}, "rounded rectangle").value();
  const AdaptiveParams ap = params_3mm_deep(8.0);
  const LinkFeedCuts c = link_feed_cuts(p, 2.0 * radius, ap);
  // How near the tool centre comes to each corner's apex (the offset arc's middle).
  double farthest = 0.0;
  for (int k = 0; k < 4; ++k) {
    const double a = deg_to_rad(-45.0 + 90.0 * k);
    const Vec2 apex = centres[k] + Vec2{std::cos(a), std::sin(a)} * (rc - radius);
    double nearest = 1e9;
    for (const Move& m : c.result.toolpath.moves) {
      nearest = std::min(nearest, distance(m.end.xy(), apex));
    }
    farthest = std::max(farthest, nearest);
  }
  const double densest = densest_link_feed_cut(c);
  std::printf("  corners reached within %.3f mm, densest link-feed move %.3f mm\n", farthest,
              densest);
  EXPECT_LE(farthest, 0.05);
  EXPECT_LE(densest, ap.stepover_mm / 25.0 + 2.0 * kCheckerPixel);
  EXPECT_LE(c.sweep.residual_mm2, 0.1);
  EXPECT_LE(c.sweep.max_gouge_mm, 1e-6);
}

// Pocket 3057 of bench/pocket_random.sh (ø20 at 40 %, a rounded outline with two bosses
// drawn across its wall): a tip visit at the top wall ended in a 0.08 mm move, shorter than
// the model's 0.25 mm pixel, that reached 0.055 mm past the cut before it. Its removal read
// as no pixel, so it ran at the link feed; the sweep found 0.45 mm^2 in it (5.6 mm of radial
// depth per mm of path, against the 8 / 25 mm a link-feed move may graze). Moves shorter than
// a pixel now run at the cutting feed.
TEST(AdaptivePocket, MovesShorterThanAPixelRunAtTheCuttingFeed) {
  const LinkFeedCuts c = expect_link_feed_grazes("random_seed3057.json", 20.0, 8.0, 5.0);
  EXPECT_LE(c.sweep.residual_mm2, 0.5);
}

// Pocket 2445 of bench/pocket_random.sh (ø20 at 40 %, a rounded rectangle with three
// bosses, 0.25 mm pixels): links ran at the link feed right up to the cut that followed
// them and from the cut before them, and the model's material edge lies up to a pixel off
// the true one, so the last 0.5 mm of one link took 0.6 mm^2 by the sweep (1.2 mm of radial
// depth at five times the feed) and the first 0.45 mm of another 0.19 mm^2. Within two
// pixels of a cut, links now run at the cutting feed. (What is left at the link feed here is
// a scallop dab's 0.75 mm into a wall: 0.42 mm.)
TEST(AdaptivePocket, LinksRunAtTheCuttingFeedWithinTwoPixelsOfACut) {
  const LinkFeedCuts c = expect_link_feed_grazes("random_seed2445.json", 20.0, 8.0, 3.0);
  EXPECT_LE(c.sweep.residual_mm2, 0.5);
}

// The scallop dabs and rides cut wall slivers by design and run at the cutting feed. They
// went at the link feed wherever the re-simulation read their cut as a graze, and the pixels
// see less of a wall sliver than is there: on this pocket (ø16 at 40 %, the dabs' test
// pocket) they added 3.25 mm^2 to what the link-feed moves remove by the sweep, up to 0.44
// mm of radial depth in one move (part-like pockets 2409, 2422, 2444: dabs 0.41-0.47 mm,
// against the 0.26-0.24 mm a link-feed move may graze). Now they add nothing there.
TEST(AdaptivePocket, ScallopDabsAndRidesRunAtTheCuttingFeed) {
  double link_removal[2] = {0.0, 0.0}, residual[2] = {0.0, 0.0};
  for (int with = 0; with < 2; ++with) {
    AdaptiveParams ap = params_3mm_deep(6.4);
    ap.wall_scallop_mm = with ? 0.1 : 0.0;
    const LinkFeedCuts c = link_feed_cuts("random_seed2033.json", 16.0, ap);
    for (const auto& [k, v] : c.per_move)
      link_removal[with] += v.first;
    residual[with] = c.sweep.residual_mm2;
  }
  std::printf("  link-feed removal %.3f mm^2 without the dabs, %.3f with; residual %.2f, %.2f\n",
              link_removal[0], link_removal[1], residual[0], residual[1]);
  EXPECT_LE(link_removal[1], link_removal[0] + 0.05);
  // And the dabs take the scallops: three quarters of what the path leaves without them at
  // least (0.40 -> 0.08 mm^2 here since session 26, whose path leaves less by itself; the
  // test asked for 0.5 mm^2 less before).
  EXPECT_LE(residual[1], 0.25 * residual[0]);
}

// What the links cost along the walls: the pocket cut with `tool_d` at `stepover_mm`, swept
// at `pixel`; the cutting length (engagement over 2 degrees) at the link feed, and at the
// cutting feed below 10 degrees.
struct WallGrazes {
  testing::SweepReport sweep;
  double link_feed_cut = 0.0, grazes = 0.0;
};
WallGrazes wall_grazes(const Pocket& p, double tool_d, double stepover_mm, double pixel,
                       double wall_tol) {
  const AdaptiveParams ap = params_3mm_deep(stepover_mm);
  auto r = adaptive_pocket(p, flat_mill(tool_d), ap);
  EXPECT_TRUE(r.ok()) << r.status().to_string();
  WallGrazes g;
  if (!r.ok()) return g;
  std::vector<testing::SweepSample> samples;
  g.sweep = testing::sweep_check(p.region, 0.5 * tool_d, r->toolpath, r->target_engagement_deg,
                                 pixel, wall_tol, &samples);
  for (const auto& q : samples) {
    if (q.engagement_deg <= 2.0) continue;
    const Move& m = r->toolpath.moves[q.move];
    if (m.feed_mm_min >= ap.rapid_mm_min) {
      g.link_feed_cut += q.length_mm;
    } else if (q.engagement_deg < 10.0) {
      g.grazes += q.length_mm;
    }
  }
  std::printf(
      "  of %.0f mm of cut: %.1f mm at the link feed, %.1f mm at 2-10 degrees; within "
      "+-20 %% %.1f %%\n",
      g.sweep.cutting_length_mm, g.link_feed_cut, g.grazes, 100.0 * g.sweep.within_20pct);
  return g;
}

// What the wall tests below hold a swept pocket to: at most `link_feed_share` of the cut at
// the link feed and `graze_share` of it grazing at 2-10 degrees (a negative share: not
// checked), `within20` of it within +-20 %, no gouge and at most 0.1 mm^2 left.
void expect_walls_kept(const WallGrazes& g, double link_feed_share, double graze_share,
                       double within20) {
  const auto& s = g.sweep;
  EXPECT_LE(g.link_feed_cut, link_feed_share * s.cutting_length_mm);
  if (graze_share >= 0.0) {
    EXPECT_LE(g.grazes, graze_share * s.cutting_length_mm);
  }
  EXPECT_GE(s.within_20pct, within20);
  EXPECT_LE(s.max_gouge_mm, 1e-6);
  EXPECT_LE(s.residual_mm2, 0.1);
}

// Fronts that meet a wall at an angle leave scallops between their arrivals, and the passes
// that reach it by the pixels a skin of up to half a pixel: both lie below the generator's
// pixels. The links that ran back along a wall on its exact offset grazed them all, and so
// did the boundary-following rides at the path's end: on the PCB-vice bar, by a sweep at
// half the bench's pixel, 60 mm of link-feed moves and 75 mm at the cutting feed cut at
// 2-10 degrees (three long moves along its diagonal walls), and the band read 91.9 %
// (95.8 % at the bench's pixel). Links over cleared floor now keep the wall scallop's
// height off the walls they run along (session 48): 7.6 and 8.2 mm, 96.2 %; twice that
// height, rising 1 in 2 (session 57): 2.2 and 9.7 mm, 96.7 %.
TEST(AdaptivePocket, LinksAlongAWallKeepOffWhatThePassesLeaveOnIt) {
  expect_walls_kept(wall_grazes(load("pcbvicebar_slice.json"), 6.0, 0.6, 0.015, 0.2), 0.005, 0.01,
                    0.95);
}

// The same on a gear (24 teeth, keyed bore; tests/data/pocket/SOURCES.md) at the bench's
// sweep pixel: its passes end on the walls between the teeth, and the links leaving them ran
// their first half millimetre within the scallops' height of the wall (the lift grew 1 in
// 5), and along it at that height, where the scallops' tips reach: 44 mm of link-feed moves
// cutting at 4-15 degrees by the sweep, 1.3 % of the cut, and 94.0 % within +-20 %, until
// session 57. Links now keep twice the scallop height off the walls and lift 1 in 2: 20 mm
// (0.6 %), 94.7 %.
TEST(AdaptivePocket, LinksLeavingAWallClearTheScallopsOnIt) {
  expect_walls_kept(wall_grazes(load("gear24.dxf"), 10.0, 1.0, 0.05, kWallTol), 0.01, -1.0, 0.945);
}

// Random pocket 723 (ø6 at 10 %, a rectangle with a round and a square island), swept at
// the bench's pixel: a link along a wall is lifted off it point by point, and each lifted
// point was kept only if the move there kept the reach off the walls. The raw path's points
// along a wall lie up to a few microns inside the reach (they are put on its offset later),
// so the move out of the link's first point never did, and no point of any link along a
// wall was lifted: they rode the offset at the cutting feed, grazing the scallops the
// passes leave (44.5 mm of the 2640 mm of cut at 2-10 degrees, 92.9 % within +-20 %). The
// move may now come as near as the point it leaves: 23.8 mm, 93.7 %.
TEST(AdaptivePocket, LinksLiftOffAWallFromPointsOnItsOffset) {
  expect_walls_kept(wall_grazes(load("random_seed723.json"), 6.0, 0.6, 0.03, kWallTol), 0.005, 0.01,
                    0.935);
}

// Random pocket 3001 (ø10 at 40 %: a 115.9 x 66.4 mm rectangle with two square islands and
// a round one, drawn to overlap each other and the wall), swept at the bench's pixel. Its
// fronts meet the walls at an angle and leave scallops between their arrivals. A link's
// point on a wall's offset was lifted only where the tool's disk there, grown by two
// pixels, held no material at all, and beside those scallops it always did: the links back
// along the walls rode them at the cutting feed, 41.9 mm of cut at 2-10 degrees by the
// sweep and 82.8 % within +-20 %, until session 63. A lift is now refused only for material
// that the lifted disk comes nearer to: 28.1 mm, 83.8 %.
TEST(AdaptivePocket, LinksLiftOffTheScallopsTheyRunBeside) {
  expect_walls_kept(wall_grazes(load("random_seed3001.json"), 10.0, 4.0, 0.05, kWallTol), 0.005,
                    0.02, 0.835);
}

}  // namespace
}  // namespace swarf
