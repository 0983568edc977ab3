// Regression tests on pockets drawn by bench/random_pocket.py (tests/data/pocket/random_seed*):
// each a shape where an earlier version gouged, left material or cut a full slot, generated
// and judged by the independent sweep of tests/pocket/sweep_checker.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "pocket/adaptive_test_util.h"
#include "pocket/sweep_checker.h"
#include "swarf/pocket/adaptive.h"

namespace swarf {
namespace {

using testing::expect_random_pocket_correct;
using testing::flat_mill;
using testing::generate;
using testing::kWallTol;
using testing::load_test_pocket;
using testing::Outcome;
using testing::params_3mm_deep;
using testing::run;
using testing::sweep_of;

// Pocket 48 of bench/pocket_random.sh: an L with four islands, ø12 at 15 %. Before session
// 7 it kept 211 mm^2 of reachable material (resume search, new entries); then a path
// point stayed 4 um inside the wedge between the round island and a square island's
// corner, which alternating projections left after 16 rounds (push_out_of_walls). Its
// near slot next to that wedge (0.5 mm, largest engagement 166 degrees) went with session
// 17's lost-entry fix (RandomPocketWithTwoEntriesInARow): 146 degrees at most now.
TEST(AdaptivePocket, RandomPocketWithWedgesBetweenIslands) {
  const Outcome o = expect_random_pocket_correct("random_seed48.json", 12.0, 1.8);
  EXPECT_GE(o.sweep.within_20pct, 0.82);
}

// Pocket 132 of bench/pocket_random.sh, ø16 at 15 %: the tool centres' region ends in a
// wedge between the bottom wall and the corner of an island 15.6 mm from it (less than the
// tool's 16). The path's nearest point was 0.9 mm from the wedge's tip, and neither the
// straight way there nor one through its midpoint kept off the corner's arc: 11.5 mm^2 left
// in the sweep. The visit now goes by more points pushed out of the walls.
TEST(AdaptivePocket, RandomPocketWhoseCentresEndInAWedgeRoundAnIslandCorner) {
  const Outcome o = expect_random_pocket_correct("random_seed132.json", 16.0, 2.4);
  EXPECT_LE(o.sweep.residual_mm2, 0.5);
}

// Pocket 504 of bench/pocket_random.sh (ø20 at 30 %): below a square island the region of
// tool centres ends in two tips 0.7 mm apart (the island's offset cuts the offset corner of
// the outer wall). The path came 4.5 mm from one and 5.08 mm from the other, beyond the
// tip visits' reach of 5 mm, and the sweep found a crescent of 11 mm^2 beside the island;
// the farther tip is now visited from the nearer one.
TEST(AdaptivePocket, RandomPocketWhoseCentresEndInTwoTipsSideBySide) {
  const Outcome o = expect_random_pocket_correct("random_seed504.json", 20.0, 6.0);
  EXPECT_LE(o.sweep.residual_mm2, 0.5);
}

// Pocket 1041 of bench/pocket_random.sh (ø20 at 40 %): the region of tool centres ends in
// a corner between a square island's offset and a round island's (a 40-gon). The path
// stopped 0.41 mm from the corner, and every way there along the round island's offset
// dipped inside it by a fraction of a micron (chords across the arcs round the polygon's
// vertices, between points pushed only to the bare reach), so the tip was never visited:
// a crescent of 3.3 mm^2 by the bench sweep. What is left (0.19 mm^2) are three scallops
// under a square island's edge, thinner than the ø20's 0.25 mm pixel, so the residual is
// held to that rather than to the per-corner allowance.
TEST(AdaptivePocket, RandomPocketWhoseTipLiesAlongAPolygonalRoundIsland) {
  const Outcome o = run(load_test_pocket("random_seed1041.json"), 20.0, 8.0);
  EXPECT_LE(o.sweep.max_gouge_mm, 1e-6);
  EXPECT_LE(o.sweep.residual_mm2, 0.3);
}

// Pocket 528 of bench/pocket_random.sh (ø3 at 8 %): a new entry's ramp beside a round
// island ended 4 um into it by the sweep's exact distances (the ramp's ends came from the
// pixel clearance, which can read half a pixel long beside a curved wall); ramps are held
// to the exact walls now, as every other move.
TEST(AdaptivePocket, RandomPocketWhoseRampRunsBesideARoundIsland) {
  expect_random_pocket_correct("random_seed528.json", 3.0, 0.24);
}

// Pocket 541 of bench/pocket_random.sh (ø12 at 5 %): the tool comes through a neck 0.28 mm
// wider than itself into uncut material, with no wall within reach and every move within
// theta_max cutting more than twice the target. The chooser's straight move for open space
// ploughed on at 145-177 degrees (2.3 mm of full slot by the bench sweep); it nibbles now.
TEST(AdaptivePocket, RandomPocketWhereTheToolLeavesANeckIntoUncutMaterial) {
  const Outcome o = expect_random_pocket_correct("random_seed541.json", 12.0, 0.6);
  EXPECT_LE(o.sweep.slot_length_mm, 0.5);  // the neck itself: every move there is a slot
}

// Pocket 832 of bench/pocket_random.sh (ø12 at 30 %): a round island 12.07 mm from the left
// wall, a neck 0.07 mm wider than the tool. The tool rode the wall into the neck with
// material ahead of it out to both tangent points, and the no-slot test read the arc short:
// its samples just outside the tool ran through the wall and the island near the tangent
// points and counted as no contact. 1.3 mm of full slot by the bench's sweep (0.3 mm by
// this one). Wall samples count as contact now and the test stops at 160 degrees: the
// session ends at the neck, and the neck is taken once the far side is clear (each change
// alone left 0.2-0.5 mm). Since session 59 the strip of centres in the neck is visited and
// plunged (wall_reach.cpp, corridors): this sweep reads 0.04 mm at 180 degrees where the way
// through the holes at the link feed arrives at the last one, removing nothing (its ring
// meets the hole's wall; none at 0.05 mm pixels, nor from the G-code at 0.025 mm).
TEST(AdaptivePocket, RandomPocketWhoseToolRodeAWallIntoANeckAsWideAsItself) {
  const Outcome o = expect_random_pocket_correct("random_seed832.json", 12.0, 3.6);
  EXPECT_LE(o.sweep.slot_length_mm, 0.1);
}

// Pocket 2010 of bench/pocket_random.sh (part-like, ø6 at 10 %): a tall rounded island
// 6.24 mm from the top wall, a channel 0.24 mm wider than the tool. A new entry ramped
// along the channel and its session cut nothing; the next session began with another entry
// at once. Post-processing made only the last entry of that stretch, so the ramp's cut
// was missing from the final path and its moves along the channel, light in the raw path,
// went through it at full depth in a full slot: 5.8 mm by the bench's sweep of the G-code,
// 4.2 mm at 170-180 degrees by the final path's own re-simulation (this test's sweep, at its
// coarser pixel, read 169 degrees at most there). Now the re-simulation reads 141 at most.
TEST(AdaptivePocket, RandomPocketWithTwoEntriesInARow) {
  const Outcome o = expect_random_pocket_correct("random_seed2010.json", 6.0, 0.6);
  EXPECT_EQ(o.sweep.slot_length_mm, 0.0);
  double slot_mm = 0.0;
  for (const AdaptiveStep& s : o.result.steps)
    if (s.kind != StepKind::kLink && s.engagement_deg >= 170.0) slot_mm += s.length_mm;
  EXPECT_EQ(slot_mm, 0.0);
}

// Pocket 2130 of bench/pocket_random.sh (part-like, ø8 at 8 %): a ring round a rounded
// block, its bottom channel 8.17 mm wide (0.17 mm of room), its left one 15.3 mm. In the
// bottom channel every move on is a slot, so the no-slot rule ended each resumed session
// after a step or two, the next resume came back 0.25 mm further, and the 200 sessions ran
// out before the left channel was reached: 790 mm^2 left. From the sixth short session in a
// row that the rule ends within a tool diameter of the last (the third until session 18),
// the slot may be cut.
TEST(AdaptivePocket, RandomPocketWithAChannelBarelyWiderThanTheToolAndAnotherBeyondIt) {
  const Outcome o = expect_random_pocket_correct("random_seed2130.json", 8.0, 0.64);
  EXPECT_LE(o.sweep.residual_mm2, 0.5);
  EXPECT_LE(o.result.material_left_mm2, 0.5);
}

// Pocket 39 of bench/pocket_random.sh (a star, ø8 at 20 %): a round island 8.1 mm from the
// wall. The tool creeps into that short neck a session at a time, as in pocket 2130, but
// gets through after four sessions; when the slot was allowed from the third it cut 2.0 mm
// of it (170-178 degrees), and 0.1 mm now.
TEST(AdaptivePocket, RandomPocketWithAShortNeckAsWideAsTheTool) {
  const Outcome o = expect_random_pocket_correct("random_seed39.json", 8.0, 1.6);
  EXPECT_LE(o.sweep.slot_length_mm, 0.5);
}

// Pocket 1516 of bench/pocket_random.sh (ø8 at 30 %): the tool creeps through a neck
// 0.12-0.18 mm wider than it between a round island and the wall, plunged through; past the
// neck's last plunge it crept on, a link and three short moves, then 0.4 mm into the
// neck's far end at 108 degrees by the model, under the 110 that marks a heavy cut between
// close walls, and 179 by the sweep: 0.4 mm of full slot (1.7 mm before session 56). Heavy
// moves that close after a neck now belong to it (neck_plunges.cpp). At this test's pixel
// the sweep read 0.47 mm of slot before; 0.08 mm is left, the pass back through the neck
// (along the way the cusps were just cut on) arriving at its last plunge's hole, whose wall
// the sweep's ring meets within half a checker pixel: no material is removed there.
TEST(AdaptivePocket, RandomPocketWhoseCreepGoesOnPastANecksLastPlunge) {
  const Outcome o = expect_random_pocket_correct("random_seed1516.json", 8.0, 2.4);
  EXPECT_LE(o.sweep.slot_length_mm, 0.1);
  EXPECT_GT(o.result.neck_plunges, 0);
}

// The corner of pocket 1535 of bench/pocket_random.sh (ø10 at 5 %) beside a round island,
// where the tool barely fits: it goes straight down there, and a 0.11 mm tip visit out of
// the hole into the corner was a full slot by the sweep (0.1 mm; 135 degrees by the model,
// whose pixels miss the slivers between the hole and the walls). It plunges at the tip.
TEST(AdaptivePocket, RandomPocketWithATipVisitOutOfAStraightPlungesHole) {
  const Outcome o = expect_random_pocket_correct("random_seed1535_corner.json", 10.0, 0.5);
  EXPECT_EQ(o.sweep.slot_length_mm, 0.0);
  EXPECT_GE(o.result.straight_plunges, 1);
  EXPECT_GE(o.result.neck_plunges, 1);
}

// Pocket 617 of bench/pocket_random.sh at 10 % stepover (ø20): a channel 0.02-0.34 mm wider
// than the tool between a square island and the wall. The tool crept into its mouth past
// the island's corner, a full slot by the sweep (0.9 mm; 134-143 degrees by the model, whose
// pixels miss the slivers on both sides), and nobody travelled the 8.7 mm of it where no
// free pixel centre fits: 3.6 mm^2 was left in slivers along both walls. The mouth is
// plunged through now, and the strip of centres is visited. The 0.04 mm of slot this sweep
// still reads (none at 0.05 mm pixels) is the way through the plunged holes at the link
// feed, arriving at a hole whose wall its coarse ring meets; nothing is removed there.
TEST(AdaptivePocket, RandomPocketWithAChannelAHairWiderThanTheTool) {
  const Outcome o = expect_random_pocket_correct("random_seed617.json", 20.0, 2.0);
  EXPECT_LE(o.sweep.slot_length_mm, 0.1);
  EXPECT_GE(o.result.neck_plunges, 1);
}

// Pocket 894 of bench/pocket_random.sh (ø20 at 30 %): below a round island, beside a
// square one and above the wall, the tool fits in a patch of centres 0.2 x 0.3 mm with
// 0.05 mm of room and no pixel centre in it. Only that patch reaches 49 mm^2 there, less
// than the quarter disk the ridge search asks of a tight spot, so it was not material and
// was left. Each patch of the exactly shrunk pocket with no free pixel is a tight spot now.
TEST(AdaptivePocket, RandomPocketWithAToolPositionNoPixelCentreHolds) {
  const Outcome o = expect_random_pocket_correct("random_seed894.json", 20.0, 6.0);
  EXPECT_LE(o.sweep.residual_mm2, 0.5);
  EXPECT_EQ(o.result.straight_plunges, 1);
}

// Pocket 710 of bench/pocket_random.sh (ø16 at 30 %): between the round outline and a
// square island's top edge, nearly tangent to it, the region of tool centres is a sliver
// 0.47 mm thick at most, ending in a 6.6 degree tip. The free pixels end 4.2 mm short of
// the tip, just beyond the tip visits' reach of half the radius, and 4.7 mm^2 were left on
// both sides of the sliver; the reach of a sharp tip now grows with its sharpness.
TEST(AdaptivePocket, RandomPocketWhoseCentresEndInANearlyTangentSliver) {
  const Outcome o = expect_random_pocket_correct("random_seed710.json", 16.0, 4.8);
  EXPECT_LE(o.sweep.residual_mm2, 0.5);
}

// Pocket 6032 of bench/pocket_random.sh (ø12 at 15 %, a rectangle with an island across
// its top-right corner): a straight link's point lay within 4e-12 mm of the full lift off
// the wall, and the loop that tries the whole lift, half and a quarter, stopping by the
// lift left against a quarter of the whole, never stopped (the CLI hung).
TEST(AdaptivePocket, RandomPocketWithALinkPointAtTheFullLiftOffTheWall) {
  const Outcome o = expect_random_pocket_correct("random_seed6032.json", 12.0, 1.8);
  EXPECT_LE(o.sweep.residual_mm2, 0.5);
}

// Pocket 65 of bench/pocket_random.sh: an L with three islands, ø16 at 5 %. Resumed
// sessions that cut nothing gave up one pixel each and used up the session limit on one
// spot, leaving 1640 mm^2; they give up a tool disk now. Gouge and residual only (0.2 mm
// of near slot next to a wedge).
TEST(AdaptivePocket, RandomPocketWhereResumesCutNothing) {
  // The sweep at 0.25 mm (a 16 mm tool spans 64 of its pixels; 11 m of path at 0.08 mm took
  // 27 s), material within 0.5 mm of a wall not counted.
  const auto s = sweep_of("random_seed65.json", 16.0, 0.8, 0.25, 0.5);
  EXPECT_LE(s.max_gouge_mm, 1e-6);
  EXPECT_LE(s.residual_mm2, 1.0);
  EXPECT_GE(s.within_20pct, 0.835);  // 0.85 before session 49's sweep
}

// ø16 at 40 % stepover: 0.2 mm pixels. Passes that ride a wall are put on its exact offset;
// the last pass round a round island rides up to 2 pixels off it there, and a snap of 1.25
// pixels for every pass (better elsewhere) left hairs of up to 0.5 mm on the islands: 3.6
// mm^2 by the bench's sweep. The snap takes the last pass along a stretch of wall up to 2
// pixels (adaptive.cpp, snap_to_wall_offset).
TEST(AdaptivePocket, LastPassAroundRoundIslandsWithCoarsePixelsCutsThemToSize) {
  const auto s = sweep_of("random_seed41.json", 16.0, 6.4, 0.12, 0.2);
  EXPECT_LE(s.max_gouge_mm, 1e-6);
  EXPECT_LE(s.residual_mm2, 1.0);
  EXPECT_GE(s.within_20pct, 0.79);  // 0.80 before session 49's sweep
}

// Pocket 144 of bench/pocket_random.sh: a ø20 in a seven-pointed outline with two islands,
// simulated with the rule's 0.25 mm pixels. Material beside the round island is reached only
// from a patch of tool centres with 0.15 mm of room beyond the radius: less than the 0.75
// pixel of room the new-entry search's medial axis asks for, and no helix or ramp fits in
// it. It was left (179 mm^2 by the sweep). A straight plunge into it, placed on the medial
// axis of every free centre and checked against the walls by exact geometry, now takes it.
// The sweep still finds about 1 mm^2 there, where no 0.25 mm pixel centre is free.
TEST(AdaptivePocket, RandomPocketWithMaterialBehindAPatchOfCentresThinnerThanAPixel) {
  const Pocket p = load_test_pocket("random_seed144.json");
  const Outcome o = run(p, 20.0, 6.0);
  EXPECT_LE(o.sweep.max_gouge_mm, 1e-6);
  EXPECT_GE(o.result.straight_plunges, 1);
  EXPECT_LE(o.sweep.residual_mm2, 2.0);
}

// Every ramp entry leaves its slot at full depth: checked on the program's own ramp moves
// (MoveKind::kRamp, the descents and the pass at depth), by the lowest the flat tool's end
// comes over points along the ramp's line. Pocket 996 of bench/pocket_random.sh (ø20 at 8 %)
// ramps twice; one ramp's last descent ended at its far end and left a wedge one descent
// thick (0.15 mm) that the path later crossed at the link feed (4.3 mm of radial depth at
// the floor by the 2D sweep). The ramps now take an even number of descents and a pass back.
TEST(AdaptivePocket, RampEntriesLeaveTheirSlotAtFullDepth) {
  const Pocket p = load_test_pocket("random_seed996.json");
  auto r = adaptive_pocket(p, flat_mill(20.0), params_3mm_deep(1.6));
  ASSERT_TRUE(r.ok()) << r.status().to_string();
  const auto& mv = r->toolpath.moves;
  const double radius = 10.0;
  int ramps = 0;
  for (std::size_t k = 1; k < mv.size();) {
    if (mv[k].kind != MoveKind::kRamp) {
      ++k;
      continue;
    }
    // One entry: moves k .. e - 1, starting from mv[k - 1].end (the ramp's first end).
    std::size_t e = k;
    while (e < mv.size() && mv[e].kind == MoveKind::kRamp)
      ++e;
    ++ramps;
    const Vec2 a = mv[k - 1].end.xy(), b = mv[k].end.xy();
    const double floor_z = mv[e - 1].end.z;
    double worst = -1e9;  // over points of the line, the lowest the tool's end reaches there
    for (int q = 0; q <= 100; ++q) {
      const Vec2 pt = a + (b - a) * (q / 100.0);
      double lowest = 1e9;
      for (std::size_t m = k; m < e; ++m) {
        const Vec3 from = mv[m - 1].end, to = mv[m].end;
        for (int t = 0; t <= 200; ++t) {
          const Vec3 c = from + (to - from) * (t / 200.0);
          if (distance(c.xy(), pt) <= radius) lowest = std::min(lowest, c.z);
        }
      }
      worst = std::max(worst, lowest);
    }
    std::printf("  ramp %d: %.2f mm long, floor %.3f, highest left on its line %.4f\n", ramps,
                distance(a, b), floor_z, worst);
    EXPECT_LE(worst, floor_z + 1e-9);
    k = e;
  }
  EXPECT_GE(ramps, 2);
}

// Pocket 317 of bench/pocket_random.sh: a ø20 between a square island and a round wall 20.2
// mm apart fits along a patch of tool centres 0.22 mm wide (0.11 mm of room each side), in
// which no pixel centre of the 0.25 mm simulation is free. The model sampled its free
// positions at pixel centres only, so the 328 mm^2 beside the island were not even material:
// left, and reported as cleared. The exact free positions between pixel centres now count
// (make_model), and straight plunges there take that material.
TEST(AdaptivePocket, RandomPocketWithMaterialReachedOnlyBetweenPixelCentres) {
  const Pocket p = load_test_pocket("random_seed317.json");
  auto r = generate(p, 20.0, 4.0);
  ASSERT_TRUE(r.ok()) << r.status().to_string();
  EXPECT_GE(r->straight_plunges, 1);
  EXPECT_LE(r->material_left_mm2, 8.0);  // the generator's own count agrees with the sweep
  // A 0.1 mm checker pixel: the pocket is 120 mm across.
  const auto s =
      testing::sweep_check(p.region, 10.0, r->toolpath, r->target_engagement_deg, 0.1, kWallTol);
  std::printf("  residual %.2f mm2, gouge %.4f mm\n", s.residual_mm2, s.max_gouge_mm);
  EXPECT_LE(s.max_gouge_mm, 1e-6);
  EXPECT_LE(s.residual_mm2, 6.0);
}

}  // namespace
}  // namespace swarf
