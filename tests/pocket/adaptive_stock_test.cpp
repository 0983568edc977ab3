// The adaptive pocket's stock-to-leave and milling-direction options, judged by the
// independent sweep (tests/pocket/sweep_checker.cpp) and by the program's own heights.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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

Pocket l_pocket_60x48() {
  Pocket l = testing::scaled(testing::load_test_pocket("l_pocket_islands.json"), 0.6);
  l.source = "L 60x48 with islands";
  return l;
}

Pocket round_pocket(double radius_mm) {
  Ring r;
  for (int k = 0; k < 180; ++k)
    r.push_back(Vec2{std::cos(kPi * k / 90), std::sin(kPi * k / 90)} * radius_mm);
  return make_pocket(r, {}, "round").value();
}

AdaptiveResult generate(const Pocket& p, double tool_d, const AdaptiveParams& ap) {
  auto r = adaptive_pocket(p, flat_mill(tool_d), ap);
  EXPECT_TRUE(r.ok()) << r.status().to_string();
  return r.ok() ? r.value() : AdaptiveResult{};
}

testing::SweepReport sweep(const PolygonSet& region, double tool_d, const AdaptiveResult& r) {
  const auto s = testing::sweep_check(region, 0.5 * tool_d, r.toolpath, r.target_engagement_deg,
                                      kCheckerPixel, kWallTol);
  std::printf("  gouge %.4f mm, residual %.2f mm2, within20 %.1f %%, slot %.1f mm\n",
              s.max_gouge_mm, s.residual_mm2, 100 * s.within_20pct, s.slot_length_mm);
  return s;
}

// Wall stock: judged on the pocket shrunk by the stock, the tool never comes nearer the walls
// and islands than the stock and clears up to it; judged on the pocket itself, the band
// between kWallTol and the stock is left all round (a path that ignored the stock would
// leave nothing there).
TEST(AdaptivePocketStock, WallStockIsLeftOnWallsAndIslands) {
  const Pocket l = l_pocket_60x48();
  AdaptiveParams ap = params_3mm_deep(1.6);
  ap.wall_stock_mm = 0.5;
  const AdaptiveResult r = generate(l, 8.0, ap);
  const PolygonSet shrunk = offset(l.region, -ap.wall_stock_mm);
  const auto inner = sweep(shrunk, 8.0, r);
  // The shrunk outline's round joins are chords within 1 um of the true offset.
  EXPECT_LE(inner.max_gouge_mm, 0.002);
  EXPECT_LE(inner.residual_mm2, 0.5);
  const auto outer = sweep(l.region, 8.0, r);
  EXPECT_LE(outer.max_gouge_mm, 0.0);
  // The band 0.25 to 0.5 mm off the walls (more is left in the corners).
  const double band_mm2 = (ap.wall_stock_mm - kWallTol) * perimeter(shrunk);
  EXPECT_GE(outer.residual_mm2, 0.8 * band_mm2);
}

// Floor stock: no move goes below the top minus the depth plus the floor stock, and the
// floor pass is at exactly that height.
TEST(AdaptivePocketStock, FloorStockIsLeftOnTheFloor) {
  const Pocket l = l_pocket_60x48();
  AdaptiveParams ap = params_3mm_deep(1.6);
  ap.stepdown_mm = 1.0;
  ap.floor_stock_mm = 0.4;
  const AdaptiveResult r = generate(l, 8.0, ap);
  double lowest = 1e9;
  for (const Move& mv : r.toolpath.moves)
    lowest = std::min(lowest, mv.end.z);
  EXPECT_NEAR(lowest, ap.top_z_mm - ap.depth_mm + ap.floor_stock_mm, 1e-9);
  const auto s = sweep(l.region, 8.0, r);
  EXPECT_LE(s.max_gouge_mm, 0.0);
  EXPECT_LE(s.residual_mm2, 0.4);
}

// The turning sense of the cutting moves about the centre of a round pocket: a spiral
// growing outwards with the material on its right (climb milling, spindle M3) turns
// counter-clockwise; conventional milling turns the other way. Both clear the pocket.
double turning_sense(const Toolpath& t) {
  double sum = 0.0;
  for (std::size_t k = 1; k < t.moves.size(); ++k) {
    const Move& a = t.moves[k - 1];
    const Move& b = t.moves[k];
    if (b.kind != MoveKind::kFeed || !b.cutting || b.end.z > -2.9) continue;
    const Vec2 p{a.end.x, a.end.y}, q{b.end.x, b.end.y};
    sum += cross(p, q - p);
  }
  return sum;
}

TEST(AdaptivePocketStock, ConventionalMillingTurnsTheOtherWay) {
  const Pocket p = round_pocket(20.0);
  AdaptiveParams ap = params_3mm_deep(1.2);
  const AdaptiveResult climb = generate(p, 6.0, ap);
  ap.climb = false;
  const AdaptiveResult conventional = generate(p, 6.0, ap);
  EXPECT_GT(turning_sense(climb.toolpath), 0.0);
  EXPECT_LT(turning_sense(conventional.toolpath), 0.0);
  for (const AdaptiveResult* r : {&climb, &conventional}) {
    const auto s = sweep(p.region, 6.0, *r);
    EXPECT_LE(s.max_gouge_mm, 0.0);
    EXPECT_LE(s.residual_mm2, 0.1);
    EXPECT_GE(s.within_20pct, 0.9);
  }
}

// Pocket 24 of bench/pocket_random.sh (ø16 at 40 %, conventional, 0.3 mm of wall stock):
// the raw path's idle tails (moves cutting at most 4 % of a target step) are dropped, but
// the pixels they had cut stayed cut in the stock; the bench sweep found 1.1 mm^2 of such crumbs
// in crescents beside the round island. The stock gets them back now, and later moves
// take most of them.
TEST(AdaptivePocketStock, RandomPocketWhereDroppedIdleMovesLeftCrumbs) {
  const Pocket p = testing::load_test_pocket("random_seed24.json");
  AdaptiveParams ap = params_3mm_deep(6.4);
  ap.wall_stock_mm = 0.3;
  ap.climb = false;
  const AdaptiveResult r = generate(p, 16.0, ap);
  const auto s = sweep(offset(p.region, -ap.wall_stock_mm), 16.0, r);
  EXPECT_LE(s.max_gouge_mm, 0.002);
  EXPECT_LE(s.residual_mm2, 0.4);  // 0.61 before
}

// --arcs: the plain fit holds the replaced points within 5 um of each arc, and the path
// rides the walls 2 um off, so arcs along the round island ran up to 3-4 um into it (the
// sweep of the benchmark L and of 37 of 49 random pockets). fit_pocket_arcs vetoes an arc
// that comes nearer a wall than radius + wall stock, by exact arc-to-edge distance, and
// still fits arcs everywhere else.
TEST(AdaptivePocketStock, FittedArcsKeepOffTheWallsAndTheWallStock) {
  const Pocket l = l_pocket_60x48();
  for (double stock : {0.0, 0.5}) {
    AdaptiveParams ap = params_3mm_deep(1.6);
    ap.wall_stock_mm = stock;
    const AdaptiveResult r = generate(l, 8.0, ap);
    const PolygonSet region = stock > 0.0 ? offset(l.region, -stock) : l.region;
    const double chords = stock > 0.0 ? 1e-3 : 1e-6;  // the offset's round joins are chords
    auto arcs_in = [](const Toolpath& tp) {
      return std::count_if(tp.moves.begin(), tp.moves.end(),
                           [](const Move& m) { return m.kind == MoveKind::kArc; });
    };
    const Toolpath plain = fit_arcs(r.toolpath);
    const Toolpath safe = fit_pocket_arcs(r.toolpath, l, 4.0, stock);
    const auto s =
        testing::sweep_check(region, 4.0, safe, r.target_engagement_deg, kCheckerPixel, kWallTol);
    const auto sp =
        testing::sweep_check(region, 4.0, plain, r.target_engagement_deg, kCheckerPixel, kWallTol);
    std::printf("  stock %.1f: arcs %ld (plain fit %ld), gouge %.4f mm (plain fit %.4f)\n", stock,
                static_cast<long>(arcs_in(safe)), static_cast<long>(arcs_in(plain)), s.max_gouge_mm,
                sp.max_gouge_mm);
    EXPECT_LE(s.max_gouge_mm, chords);
    EXPECT_GE(arcs_in(safe), arcs_in(plain) * 8 / 10);
    EXPECT_GT(arcs_in(safe), 10);
    EXPECT_LE(s.residual_mm2, sp.residual_mm2 + 0.05);
  }
}

// Pocket 2033 of bench/pocket_random.sh (a U, ø16 at 40 %): the passes meet the long
// bottom wall at an angle and turn back, and between two arrivals the wall kept a scallop
// up to 0.35 mm high (the bench's sweep: 1.47 mm^2 beyond 0.2 mm from the walls, in eight
// bumps). Once the path is done, the tool takes each scallop higher than wall_scallop_mm off,
// square to the wall, at a cost of a few mm of cutting.
TEST(AdaptivePocketStock, ScallopsLeftOnTheWallsAtAHighStepoverAreTakenOff) {
  const Pocket p = testing::load_test_pocket("random_seed2033.json");
  AdaptiveParams ap = params_3mm_deep(6.4);
  const AdaptiveResult r = generate(p, 16.0, ap);
  ap.wall_scallop_mm = 0.0;
  const AdaptiveResult none = generate(p, 16.0, ap);
  // Material from 0.2 mm off the walls counts here (the bench's allowance; the tests' usual
  // kWallTol is 0.25). Lower scallops are below the simulation's pixels at this tool size.
  auto swept = [&](const AdaptiveResult& a) {
    const auto s = testing::sweep_check(p.region, 8.0, a.toolpath, a.target_engagement_deg,
                                        kCheckerPixel, 0.2);
    std::printf("  residual %.2f mm2, within20 %.1f %%, cutting %.0f mm, gouge %.4f mm\n",
                s.residual_mm2, 100 * s.within_20pct, s.cutting_length_mm, s.max_gouge_mm);
    return s;
  };
  const auto s = swept(r), s_none = swept(none);
  // The scallops are there without the dabs (0.97 mm^2 since session 26, whose path leaves
  // less by itself; over 1.0 before), and the dabs take three quarters of them at least.
  EXPECT_GE(s_none.residual_mm2, 0.5);
  EXPECT_LE(s.residual_mm2, 0.15);
  EXPECT_LE(s.residual_mm2, 0.25 * s_none.residual_mm2);
  EXPECT_LE(s.max_gouge_mm, 1e-6);
  EXPECT_EQ(s.slot_length_mm, 0.0);
  EXPECT_LE(s.cutting_length_mm, s_none.cutting_length_mm + 20.0);
  EXPECT_GE(s.within_20pct, s_none.within_20pct - 0.02);
  EXPECT_LE(r.material_left_mm2, 0.1);
  // Each dab is a visit from the last pass near its scallop, there and back: no lift is
  // added, and the 26 dabs cost 3.2 s here (the bench's sweep at 6 mm deep: 110 -> 112 s;
  // a tour of them after the path's end, 114 s and 265 mm more of links). Since session 23
  // the dabs' cuts run at the cutting feed whatever the re-simulation reads
  // (ScallopDabsAndRidesRunAtTheCuttingFeed), and so do the links' last and first two
  // pixels next to them (LinksRunAtTheCuttingFeedWithinTwoPixelsOfACut): 6.4 s.
  const ToolpathMetrics mr = compute_metrics(r.toolpath), mn = compute_metrics(none.toolpath);
  std::printf("  machining %.1f s (without %.1f s), lifts %zu (%zu)\n", mr.machining_time_s,
              mn.machining_time_s, mr.lift_offs, mn.lift_offs);
  EXPECT_EQ(mr.lift_offs, mn.lift_offs);
  EXPECT_LE(mr.machining_time_s, mn.machining_time_s + 7.5);
}

// Where the scallops stay below wall_scallop_mm (ø8 at 10 %: R - sqrt(R^2 - (ae / 2)^2) =
// 0.02 mm where a pass meets a wall square), the path is the same with and without the
// option: nothing is added.
TEST(AdaptivePocketStock, LowScallopsGetNoDabs) {
  const Pocket l = l_pocket_60x48();
  AdaptiveParams ap = params_3mm_deep(0.8);
  const AdaptiveResult r = generate(l, 8.0, ap);
  ap.wall_scallop_mm = 0.0;
  const AdaptiveResult none = generate(l, 8.0, ap);
  ASSERT_EQ(r.toolpath.moves.size(), none.toolpath.moves.size());
  for (std::size_t k = 0; k < r.toolpath.moves.size(); ++k)
    EXPECT_EQ(r.toolpath.moves[k].end, none.toolpath.moves[k].end);
}

}  // namespace
}  // namespace swarf
