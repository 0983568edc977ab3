// The independent sweep itself, against closed forms: what it counts as cut and as left.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "pocket/sweep_checker.h"
#include "swarf/core/vec.h"

namespace swarf {
namespace {

Move move_to(MoveKind kind, Vec3 end) {
  Move m;
  m.kind = kind;
  m.end = end;
  m.feed_mm_min = kind == MoveKind::kRapid ? 0.0 : 300.0;
  m.cutting = kind != MoveKind::kRapid;
  return m;
}

// A straight plunge and straight back up, no move along the floor: the disk where the tool
// reached the floor is cut. The sweep used to read only moves along the floor and counted
// such a plunge as cutting nothing. A 20 mm square and a ø10 tool: the tool reaches the
// square less its four corners (4 (1 - pi / 4) 25 mm^2), and the plunge at the middle takes
// a disk of 25 pi.
TEST(SweepChecker, AStraightPlungeCutsItsDisk) {
  const PolygonSet square{{Ring{{0, 0}, {20, 0}, {20, 20}, {0, 20}}}};
  Toolpath tp;
  tp.moves = {move_to(MoveKind::kRapid, {10, 10, 5}), move_to(MoveKind::kPlunge, {10, 10, -1}),
              move_to(MoveKind::kRapid, {10, 10, 5})};
  const auto s = testing::sweep_check(square, 5.0, tp, 36.87, 0.05, 0.0);
  // Cells are counted whole: within half a 0.05 mm cell along the 80 mm of walls.
  const double reach = 400.0 - 4.0 * (1.0 - kPi / 4.0) * 25.0, pixel_band = 80.0 * 0.05 / 2;
  EXPECT_NEAR(s.unreachable_mm2, 400.0 - reach, pixel_band);
  EXPECT_NEAR(s.residual_mm2, reach - kPi * 25.0, pixel_band);
  EXPECT_EQ(s.max_gouge_mm, 0.0);
  EXPECT_EQ(s.cutting_length_mm, 0.0);  // a plunge is part of an entry, not a floor pass
}

// What belongs to an entry: the ramp's way down and its pass back along the last leg at
// the floor (the wedge that leg left), the helix's way down and its closing circle. What
// follows at the floor is cutting, an arc as much as a line. Both sweeps read the ramp's
// closing pass as a 180-degree slot before (it is a G1 at the floor, kind kFeed once read
// from G-code; 11.5 mm of "slot" on random pocket 1122), and counted no arc at the floor
// at all (a program with fitted arcs was judged on its lines only).
// A 100 x 40 box and a ø10 tool.
TEST(SweepChecker, TheEntrysClosingPassIsEntryAndWhatFollowsIsCutting) {
  const PolygonSet box{{Ring{{0, 0}, {100, 0}, {100, 40}, {0, 40}}}};
  auto arc_to = [](MoveKind kind, Vec3 end, Vec2 centre, double z) {
    Move m = move_to(kind, end);
    m.center = {centre.x, centre.y, z};
    return m;
  };
  Toolpath ramp;
  ramp.moves = {move_to(MoveKind::kRapid, {10, 20, 5}), move_to(MoveKind::kRamp, {30, 20, -0.5}),
                move_to(MoveKind::kRamp, {10, 20, -1}), move_to(MoveKind::kFeed, {30, 20, -1}),
                move_to(MoveKind::kFeed, {50, 20, -1})};
  const auto r = testing::sweep_check(box, 5.0, ramp, 60.0, 0.05, 0.0);
  EXPECT_NEAR(r.cutting_length_mm, 20.0, 0.3);  // 30 -> 50 only
  EXPECT_NEAR(r.slot_length_mm, 20.0, 0.3);
  // A helix down round (70, 20), two closing half circles, then an arc of a fitted path:
  // a half circle of radius 10 round (80, 20) from (70, 20) to (90, 20), into material.
  Toolpath helix;
  helix.moves = {move_to(MoveKind::kRapid, {72, 20, 5}),
                 arc_to(MoveKind::kHelix, {68, 20, -0.5}, {70, 20}, -0.5),
                 arc_to(MoveKind::kHelix, {72, 20, -1}, {70, 20}, -1),
                 arc_to(MoveKind::kArc, {68, 20, -1}, {70, 20}, -1),
                 arc_to(MoveKind::kArc, {72, 20, -1}, {70, 20}, -1),
                 move_to(MoveKind::kFeed, {70, 20, -1}),
                 arc_to(MoveKind::kArc, {90, 20, -1}, {80, 20}, -1)};
  helix.moves.back().clockwise = true;
  const auto h = testing::sweep_check(box, 5.0, helix, 60.0, 0.05, 0.0);
  // The first 2 mm of the arc lie in the helix's hole (7 mm round its axis).
  EXPECT_NEAR(h.cutting_length_mm, 10.0 * kPi - 2.0, 0.5);
  EXPECT_GT(h.max_engagement_deg, 120.0);
  // The same read back from G-code, whose words are rounded to 4 decimals: the closing
  // circle's centre (its start plus I, J) 1e-4 off the helix's axis is still its axis.
  helix.moves[3].center.x += 1e-4;
  helix.moves[4].center.x += 1e-4;
  const auto g = testing::sweep_check(box, 5.0, helix, 60.0, 0.05, 0.0);
  EXPECT_NEAR(g.cutting_length_mm, h.cutting_length_mm, 1e-9);
  EXPECT_EQ(g.slot_length_mm, h.slot_length_mm);
}

// The arc is read on a ring half a pixel outside the tool, so a pixel that is a large part
// of the stepover reads it wide (at 0.05 mm a ø3 at 0.15 mm read 28-30 degrees where the
// closed form is 25.8): with a pixel a twentieth of the stepover (swarf_pocket_sweep's
// rule), a straight pass beside a straight cut reads acos(1 - s / R) within a degree and a
// half, and the removal measure (area per length) reads the same. A slot at y = 3, then four
// passes each 0.15 mm further up, in a 30 x 10 mm box.
TEST(SweepChecker, APassAtAKnownStepoverReadsItsClosedFormArcWithAFinePixel) {
  const PolygonSet box{{Ring{{0, 0}, {30, 0}, {30, 10}, {0, 10}}}};
  const double r = 1.5, stepover = 0.15;
  Toolpath tp;
  for (int k = 0; k <= 4; ++k) {
    const double y = 3.0 + k * stepover;
    tp.moves.push_back(move_to(MoveKind::kRapid, {3, y, 5}));
    tp.moves.push_back(move_to(MoveKind::kPlunge, {3, y, -1}));
    tp.moves.push_back(move_to(MoveKind::kFeed, {27, y, -1}));
    tp.moves.push_back(move_to(MoveKind::kRapid, {27, y, 5}));
  }
  const double closed_form = rad_to_deg(std::acos(1.0 - stepover / r));
  std::vector<testing::SweepSample> samples;
  const auto s = testing::sweep_check(box, r, tp, closed_form, stepover / 20.0, 0.0, &samples, 0.5);
  // The fourth pass, away from its ends (where the tool enters and leaves the material).
  // Not the last: the arc counts only material that some pass removes, and the ring half a
  // pixel outside the last pass runs through what none does.
  int n = 0;
  for (const auto& q : samples) {
    if (std::abs(q.position.y - (3.0 + 3 * stepover)) > 1e-9 || q.position.x < 8 ||
        q.position.x > 22)
      continue;
    EXPECT_NEAR(q.engagement_deg, closed_form, 1.5) << q.position.x;
    ++n;
  }
  EXPECT_GT(n, 1000);
  // By removal the four passes beside a cut are in the band and the slot is not: 4 / 5 of
  // the length, less the passes' first half millimetre (a window that starts in the air).
  EXPECT_NEAR(s.within_20pct_removal, 0.8, 0.02);
}

// The milling side: a slot along the bottom wall of a 40 x 20 box (contact on both sides:
// neither), then three passes each 2 mm higher, the new material above the tool. Going -x
// the material is on the right of the motion (climb with an M3 spindle), going +x on the
// left (conventional). Two climb passes and one conventional: two thirds climb. The
// conventional pass run the other way: all climb.
TEST(SweepChecker, ClimbShareReadsWhichSideOfTheMotionTheMaterialIsOn) {
  const PolygonSet box{{Ring{{0, 0}, {40, 0}, {40, 20}, {0, 20}}}};
  auto program = [](bool third_pass_climbs) {
    Toolpath tp;
    auto pass = [&](Vec2 from, Vec2 to) {
      tp.moves.push_back(move_to(MoveKind::kRapid, {from.x, from.y, 5}));
      tp.moves.push_back(move_to(MoveKind::kPlunge, {from.x, from.y, -1}));
      tp.moves.push_back(move_to(MoveKind::kFeed, {to.x, to.y, -1}));
      tp.moves.push_back(move_to(MoveKind::kRapid, {to.x, to.y, 5}));
    };
    pass({4, 4}, {36, 4});  // the slot
    pass({36, 6}, {4, 6});  // climb
    if (third_pass_climbs)
      pass({36, 8}, {4, 8});
    else
      pass({4, 8}, {36, 8});  // conventional
    pass({36, 10}, {4, 10});  // climb
    return tp;
  };
  const auto mixed = testing::sweep_check(box, 4.0, program(false), 30.0, 0.05, 0.0);
  EXPECT_NEAR(mixed.climb_share, 2.0 / 3.0, 0.02);
  const auto climb = testing::sweep_check(box, 4.0, program(true), 30.0, 0.05, 0.0);
  EXPECT_GT(climb.climb_share, 0.99);
}

// The arc is read on a ring half a pixel outside the tool, which crosses a wall the tool
// rides along before the tool's edge does (acos(R / (R + h/2)), 5.7 degrees for a ø10 at
// 0.05 mm), and cells centred on a wall count as inside on its low-x and low-y sides only:
// the same ride read 34-35 degrees along the bottom and left walls of a rectangle and 26-27
// along the top and right ones (session 47). A 60 x 40 rectangle, upright and turned 30
// degrees, cleared by a zigzag and a lap that keep the tool's edge 0.85 mm off the walls, then
// one ride round the walls: every wall reads the closed form acos((R - 0.85) / R).
TEST(SweepChecker, ARideAlongAWallReadsItsClosedFormOnEverySideAndSlant) {
  const double r = 5.0, band = 0.85;
  const double closed_form = rad_to_deg(std::acos((r - band) / r));  // 33.9
  for (const double turn_deg : {0.0, 30.0}) {
    const double c = std::cos(deg_to_rad(turn_deg)), s = std::sin(deg_to_rad(turn_deg));
    auto at = [&](double x, double y) { return Vec2{c * x - s * y, s * x + c * y}; };
    const PolygonSet box{{Ring{at(0, 0), at(60, 0), at(60, 40), at(0, 40)}}};
    Toolpath tp;
    auto floor = [&](MoveKind kind, double x, double y) {
      const Vec2 p = at(x, y);
      return move_to(kind, {p.x, p.y, -1});
    };
    const double lo = r + band;
    tp.moves.push_back(move_to(MoveKind::kRapid, {at(lo, lo).x, at(lo, lo).y, 5}));
    tp.moves.push_back(floor(MoveKind::kPlunge, lo, lo));
    for (int row = 0; row <= 6; ++row) {
      const double y = lo + row * (40 - 2 * lo) / 6;
      if (row > 0) tp.moves.push_back(floor(MoveKind::kFeed, row % 2 == 1 ? 60 - lo : lo, y));
      tp.moves.push_back(floor(MoveKind::kFeed, row % 2 == 0 ? 60 - lo : lo, y));
    }
    // A lap round the zigzag's ends, from where it ends, leaves the band's edge straight.
    for (const auto& [x, y] :
         {std::pair{lo, 40 - lo}, {lo, lo}, {60 - lo, lo}, {60 - lo, 40 - lo}, {lo, 40 - lo}})
      tp.moves.push_back(floor(MoveKind::kFeed, x, y));
    tp.moves.push_back(floor(MoveKind::kFeed, r, 40 - r));
    const std::size_t ride = tp.moves.size();
    for (const auto& [x, y] : {std::pair{r, r}, {60 - r, r}, {60 - r, 40 - r}, {r, 40 - r}})
      tp.moves.push_back(floor(MoveKind::kFeed, x, y));
    std::vector<testing::SweepSample> samples;
    testing::sweep_check(box, r, tp, closed_form, 0.05, 0.0, &samples);
    // Each wall away from the corners, where the previous ride's band is gone.
    for (std::size_t wall = 0; wall < 4; ++wall) {
      double sum = 0.0;
      int n = 0;
      for (const auto& q : samples) {
        if (q.move != ride + wall) continue;
        const Vec2 p{c * q.position.x + s * q.position.y, -s * q.position.x + c * q.position.y};
        const bool across_x = wall % 2 == 1;  // the left wall first, then the bottom one
        const double t = across_x ? p.x : p.y, len = across_x ? 60.0 : 40.0;
        if (t < 15 || t > len - 15) continue;
        EXPECT_NEAR(q.engagement_deg, closed_form, 1.5) << turn_deg << " wall " << wall << " " << t;
        sum += q.engagement_deg;
        ++n;
      }
      ASSERT_GT(n, 150) << wall;
      EXPECT_NEAR(sum / n, closed_form, 0.5) << turn_deg << " wall " << wall;
    }
  }
}

// A slot down a channel 0.1 mm wider than the tool takes the whole front half: the ring
// crosses both walls, and read as it lies it counted 168 degrees, under the 170 of a slot.
TEST(SweepChecker, ASlotInAChannelBarelyWiderThanTheToolReadsAFullSlot) {
  const PolygonSet channel{{Ring{{0, 0}, {40, 0}, {40, 10.1}, {0, 10.1}}}};
  Toolpath tp;
  tp.moves = {move_to(MoveKind::kRapid, {5.05, 5.05, 5}),
              move_to(MoveKind::kPlunge, {5.05, 5.05, -1}),
              move_to(MoveKind::kFeed, {34.95, 5.05, -1})};
  const auto s = testing::sweep_check(channel, 5.0, tp, 36.87, 0.05, 0.0);
  EXPECT_GT(s.slot_length_mm, 29.5);  // of 29.9
  EXPECT_GT(s.max_engagement_deg, 178.0);
}

// Reversals: where the floor pass turns back by more than 135 degrees within a millimetre,
// G0 moves along the floor (another generator's keep-tool-down links) included; a half
// circle of radius 3 turns as far but over 9.4 mm, and is not one.
TEST(SweepChecker, ReversalsAreTheMachineGoingBackNotAWideTurn) {
  const PolygonSet box{{Ring{{0, 0}, {40, 0}, {40, 40}, {0, 40}}}};
  auto floor = [](MoveKind kind, double x, double y) { return move_to(kind, {x, y, -1}); };
  Toolpath zigzag;
  zigzag.moves = {move_to(MoveKind::kRapid, {5, 5, 5}), move_to(MoveKind::kPlunge, {5, 5, -1}),
                  floor(MoveKind::kFeed, 35, 5),        floor(MoveKind::kFeed, 35, 5.5),
                  floor(MoveKind::kFeed, 5, 5.5),       floor(MoveKind::kFeed, 5, 6),
                  floor(MoveKind::kFeed, 35, 6),        floor(MoveKind::kRapid, 5, 6.5),
                  floor(MoveKind::kFeed, 35, 6.5)};
  const auto z = testing::sweep_check(box, 4.0, zigzag, 30.0, 0.05, 0.0);
  EXPECT_EQ(z.reversals, 4);  // at x = 35, 5, and both ends of the rapid
  EXPECT_NEAR(z.floor_length_mm, 4 * 30.0 + 2 * 0.5 + std::hypot(30.0, 0.5), 0.05);
  Toolpath loop;
  loop.moves = {move_to(MoveKind::kRapid, {5, 5, 5}), move_to(MoveKind::kPlunge, {5, 5, -1}),
                floor(MoveKind::kFeed, 35, 5), floor(MoveKind::kArc, 35, 11),
                floor(MoveKind::kFeed, 5, 11)};
  loop.moves[3].center = {35, 8, -1};  // counter-clockwise, round (35, 8)
  const auto l = testing::sweep_check(box, 4.0, loop, 30.0, 0.05, 0.0);
  EXPECT_EQ(l.reversals, 0);
  EXPECT_NEAR(l.floor_length_mm, 60.0 + 3.0 * kPi, 0.05);
}

}  // namespace
}  // namespace swarf
