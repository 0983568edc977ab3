// Correctness of the adaptive pocket (issue item 6), judged by the independent sweep of
// tests/pocket/sweep_checker.cpp on the final toolpath.
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

using testing::expect_correct;
using testing::flat_mill;
using testing::generate;
using testing::kCheckerPixel;
using testing::kResidualPerCornerMm2;
using testing::kWallTol;
using testing::Outcome;
using testing::params_3mm_deep;
using testing::run;
using testing::scaled;

Pocket load(const std::string& name) {
  return testing::load_test_pocket(name);
}

Pocket star(double r_out, double r_in, int points) {
  Ring r;
  for (int k = 0; k < 2 * points; ++k) {
    const double a = kPi * k / points + kPi / 2;
    const double rad = k % 2 == 0 ? r_out : r_in;
    r.push_back({rad * std::cos(a), rad * std::sin(a)});
  }
  return make_pocket(r, {}, "star").value();
}

TEST(AdaptivePocket, LPocket) {
  const Pocket l = scaled(load("l_pocket_islands.json"), 0.6);
  Pocket plain = make_pocket(l.outer(), {}, "L 60x48").value();
  expect_correct(plain, run(plain, 8.0, 1.6), 0.90, 0.90);
}

TEST(AdaptivePocket, LPocketWithRoundAndRectangularIsland) {
  Pocket l = scaled(load("l_pocket_islands.json"), 0.6);
  l.source = "L 60x48 with islands";
  expect_correct(l, run(l, 8.0, 1.6), 0.85, 0.86);
}

// Round islands whose gap to the nearest walls is the tool diameter plus 0.8 mm: the
// boundary of Algorithm 4 runs round each island through uncut material, a full slot, unless
// the chooser nibbles there instead (move_chooser.cpp).
TEST(AdaptivePocket, IslandsLessThanAMillimetreFromTheWalls) {
  std::vector<Ring> islands;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 2; ++j) {
      const Vec2 c{12.0 + 20.0 * i, 12.0 + 24.0 * j};
      Ring r;
      for (int k = 0; k < 32; ++k)
        r.push_back(c + Vec2{std::cos(kPi * k / 16), std::sin(kPi * k / 16)} * 3.2);
      islands.push_back(r);
    }
  }
  const Pocket p =
      make_pocket({{0, 0}, {64, 0}, {64, 48}, {0, 48}}, islands, "64 x 48, 6 islands").value();
  expect_correct(p, run(p, 8.0, 0.8), 0.74, 0.79);
}

// A comb: four teeth 15 mm wide and 40 mm deep off a 20 mm spine (from bench/pocket_stress.sh,
// a shape no tuning used): every tooth is a dead end the tool must enter and leave.
TEST(AdaptivePocket, CombOfNarrowTeeth) {
  const Pocket p = make_pocket({{0, 0},
                                {90, 0},
                                {90, 60},
                                {75, 60},
                                {75, 20},
                                {60, 20},
                                {60, 60},
                                {45, 60},
                                {45, 20},
                                {30, 20},
                                {30, 60},
                                {15, 60},
                                {15, 20},
                                {0, 20}},
                               {}, "comb")
                       .value();
  expect_correct(p, run(p, 6.0, 1.2), 0.91, 0.91);
}

TEST(AdaptivePocket, ChannelBarelyWiderThanTheTool) {
  Pocket ch = make_pocket({{0, 0}, {40, 0}, {40, 8.8}, {0, 8.8}}, {}, "channel 8.8 x 40").value();
  const Outcome o = run(ch, 8.0, 1.6);
  expect_correct(ch, o, -1.0);
  // No helix fits: the entry is a ramp along the channel.
  EXPECT_EQ(o.result.helix_radius_mm, 0.0);
}

// The channel of random pocket 3053 (ø20, 2.1 mm of room, 60.17 mm long, walls off the
// pixel grid): the ramp's ends came from a pixel march and stopped 0.25 and 0.17 mm short of
// the exact reach; the path, snapped onto the end walls' exact offsets, then went on along
// the ramp's line by that much at full depth, a full slot (0.2 mm by the sweep). The ends now
// lie on those offsets (R + 2 um from the end walls) to within 1 um, and nothing slots.
TEST(AdaptivePocket, RampReachesTheExactEndsOfAChannel) {
  const double len = 60.17046, radius = 10.0;
  const Pocket ch =
      make_pocket({{0, 0}, {22.11662, 0}, {22.11662, len}, {0, len}}, {}, "channel 3053").value();
  const Outcome o = run(ch, 2.0 * radius, 6.0);
  expect_correct(ch, o, -1.0);
  EXPECT_EQ(o.sweep.slot_length_mm, 0.0);
  const auto& mv = o.result.toolpath.moves;
  std::size_t k = 1;
  while (k < mv.size() && mv[k].kind != MoveKind::kRamp)
    ++k;
  ASSERT_LT(k, mv.size());
  const double y0 = mv[k - 1].end.y, y1 = mv[k].end.y;
  const double lo = radius + 0.002, hi = len - radius - 0.002;  // the exact reach along the channel
  EXPECT_NEAR(std::min(y0, y1), lo, 1e-3);
  EXPECT_NEAR(std::max(y0, y1), hi, 1e-3);
  EXPECT_GE(std::min(y0, y1), lo - 1e-9);
  EXPECT_LE(std::max(y0, y1), hi + 1e-9);
}

TEST(AdaptivePocket, StarWithSharpCorners) {
  const Pocket s = star(30.0, 14.0, 5);
  expect_correct(s, run(s, 8.0, 1.6), 0.815, 0.83);  // 0.84 before session 49's sweep
}

TEST(AdaptivePocket, KirimotoPocketFromARealPart) {
  const Pocket p = load("kirimoto_pocket.json");
  expect_correct(p, run(p, 10.0, 2.0), 0.86, 0.87);
}

TEST(AdaptivePocket, PcbViceBarSliceFromARealPart) {
  const Pocket p = load("pcbvicebar_slice.json");
  // (Removal 0.79 before session 23; splitting links where their feed changes moves the
  // checker's samples along the same path: 0.787.)
  expect_correct(p, run(p, 8.0, 1.6), 0.765, 0.78);  // 0.80 before session 49's sweep
}

// Passes along a wall are put on one exact offset of it (adaptive.cpp): every floor point
// within a pixel of the wall offset sits on it to the micrometre, none is nearer the wall.
TEST(AdaptivePocket, PassesAlongAWallSitOnOneOffset) {
  const Pocket p =
      make_pocket({{0, 0}, {40, 0}, {40, 30}, {0, 30}}, {{{14, 10}, {22, 10}, {22, 16}, {14, 16}}},
                  "rectangle with an island")
          .value();
  const Outcome o = run(p, 8.0, 1.2);
  const double on = 4.0 + 0.002, h = o.result.resolution_mm;
  int on_offset = 0;
  const std::vector<Move>& mv = o.result.toolpath.moves;
  for (std::size_t i = 0; i < mv.size(); ++i) {
    const Move& m = mv[i];
    if (std::abs(m.end.z + 3.0) > 1e-9) continue;  // the floor pass
    // A point where the path goes on straight is a change of feed (a link's ends next to a
    // cut run at the cutting feed), not a path point: it lies on the chord between two.
    if (i > 0 && i + 1 < mv.size() && std::abs(mv[i + 1].end.z - m.end.z) < 1e-9) {
      const Vec2 u = m.end.xy() - mv[i - 1].end.xy(), w = mv[i + 1].end.xy() - m.end.xy();
      if (std::abs(cross(u, w)) < 1e-9 * norm(u) * norm(w) && dot(u, w) > 0) continue;
    }
    double d = 1e9;
    for (const Ring& r : p.region.rings) {
      for (std::size_t k = 0; k < r.size(); ++k) {
        const Vec2 a = r[k], b = r[(k + 1) % r.size()], ab = b - a;
        const double t = std::clamp(dot(m.end.xy() - a, ab) / norm_sq(ab), 0.0, 1.0);
        d = std::min(d, norm(m.end.xy() - (a + ab * t)));
      }
    }
    EXPECT_GE(d, on - 1e-6) << m.end.x << " " << m.end.y;
    if (d < on + h) {
      EXPECT_NEAR(d, on, 1e-6) << m.end.x << " " << m.end.y;
      ++on_offset;
    }
  }
  EXPECT_GT(on_offset, 100);
  EXPECT_EQ(o.result.gouge_steps, 0);
}

// A round island 1.9 mm from the wall in the leg of an L, under a ø3 tool (from the random
// pocket sweep of session 7): the tool comes into the wedge between wall and island, where
// the chooser's pixel test alone let a path point 6 um into the island; every point is now
// exactly clear of both (adaptive.cpp, push_out_of_walls).
TEST(AdaptivePocket, WedgeBetweenAWallAndAnIslandNearerThanTheTool) {
  Ring island;
  for (int k = 0; k < 40; ++k) {
    island.push_back(Vec2{20.0, 4.24} +
                     Vec2{std::cos(kPi * k / 20), std::sin(kPi * k / 20)} * 2.34);
  }
  const Pocket p =
      make_pocket({{0, 0}, {28.29, 0}, {28.29, 8.61}, {8.61, 8.61}, {8.61, 28.29}, {0, 28.29}},
                  {island}, "L with an island 1.9 mm from a wall")
          .value();
  const Outcome o = run(p, 3.0, 0.3);
  expect_correct(p, o, 0.82, 0.91);
  EXPECT_EQ(o.result.gouge_steps, 0);
}

// A round island 10 mm from the wall under a ø12 tool, in the middle of a rectangle (from the
// random pocket sweep of session 7). The region of tool centres runs into two long thin
// wedges under the island, and the strip along the wall beside them is reached last. The
// resume search gave up after 16 rounds of the nearest pixels, all in a wedge tip, and left
// 217 mm^2 (the strip and the tips); the tips are cut from their exact apex now.
TEST(AdaptivePocket, IslandNearlyClosingTheWayAlongAWall) {
  Ring island;
  for (int k = 0; k < 40; ++k)
    island.push_back(Vec2{40.0, 17.0} + Vec2{std::cos(kPi * k / 20), std::sin(kPi * k / 20)} * 7.0);
  const Pocket p = make_pocket({{0, 0}, {80, 0}, {80, 40}, {0, 40}}, {island},
                               "80 x 40, island 10 mm from a wall")
                       .value();
  const Outcome o = run(p, 12.0, 1.2);
  expect_correct(p, o, 0.86, 0.86);
  EXPECT_EQ(o.result.gouge_steps, 0);
}

// ø16 at 40 % stepover (78 degrees) in a plain rectangle. Once the first spiral met the
// walls, the tool reached the right wall against its milling direction, with the material
// on its other side, where the engagement falls as the move turns towards the material
// side the chooser assumes. The walk found no crossing, and Algorithm 3's scan (which stops
// at the first move worse than the best so far) took the move back into the wall at twice
// the target every second step: a zigzag along the wall, 141 degrees at most, 73.6 % of
// the cut within +-20 %. Now arcs: 117 degrees at most (in a corner), 78.5 %.
TEST(AdaptivePocket, HighStepoverAlongAWallReachedAgainstTheMillingDirection) {
  const Pocket p = make_pocket({{0, 0}, {70, 0}, {70, 50}, {0, 50}}, {}, "70 x 50").value();
  const Outcome o = run(p, 16.0, 6.4);
  expect_correct(p, o, -1.0);
  EXPECT_EQ(o.sweep.slot_length_mm, 0.0);
  EXPECT_LE(o.sweep.max_engagement_deg, 1.6 * o.result.target_engagement_deg);
  EXPECT_GE(o.sweep.within_20pct, 0.77);
}

TEST(AdaptivePocket, ToolTooLargeAndNoEntryAreNamedErrors) {
  Pocket narrow = make_pocket({{0, 0}, {40, 0}, {40, 5}, {0, 5}}, {}, "narrow").value();
  Tool t;
  t.diameter_mm = 6.0;
  auto r = adaptive_pocket(narrow, t, AdaptiveParams{});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), Error::kToolTooLarge);
  // A square just wider than the tool: it fits, but there is no room to helix or ramp; with
  // straight plunges turned off that is an error.
  Pocket tight = make_pocket({{0, 0}, {6.25, 0}, {6.25, 6.25}, {0, 6.25}}, {}, "tight").value();
  AdaptiveParams no_plunge;
  no_plunge.straight_plunge = false;
  auto q = adaptive_pocket(tight, t, no_plunge);
  ASSERT_FALSE(q.ok());
  EXPECT_EQ(q.status().code(), Error::kNoEntryFound) << q.status().to_string();
}

// The same square with the default: the tool goes straight down at its centre (no helix of
// 0.1 mm would cut anything else) and leaves nothing it can reach.
TEST(AdaptivePocket, PocketBarelyWiderThanTheToolIsEnteredStraightDown) {
  Pocket tight = make_pocket({{0, 0}, {6.25, 0}, {6.25, 6.25}, {0, 6.25}}, {}, "tight").value();
  const Outcome o = run(tight, 6.0, 0.6);
  EXPECT_EQ(o.result.straight_plunges, 1);
  EXPECT_LE(o.sweep.max_gouge_mm, 1e-6);
  EXPECT_LE(o.sweep.residual_mm2, kResidualPerCornerMm2 * 4);
  const auto plunge = std::find_if(o.result.toolpath.moves.begin(), o.result.toolpath.moves.end(),
                                   [](const Move& mv) { return mv.kind == MoveKind::kPlunge; });
  ASSERT_NE(plunge, o.result.toolpath.moves.end());
  EXPECT_NEAR(plunge->end.x, 3.125, 0.1);
  EXPECT_NEAR(plunge->end.y, 3.125, 0.1);
}

// On layers below the first, an entry's hole or slot is already cut down to the previous
// layer's floor (the path is the same on every layer): the tool goes straight down through
// it and the helix or ramp starts at that floor, not 1 mm above it in the air (3.8 s a
// layer at the defaults). Checked on the program's own moves: no helix or ramp move starts
// above the floor of the layer before its own, on the L (helix) and on a channel as wide as
// the tool plus 0.8 mm (ramp); the first layer's still start 1 mm above the stock.
TEST(AdaptivePocket, LowerLayersEnterThroughTheHoleAlreadyCut) {
  Pocket channel =
      make_pocket({{0, 0}, {40, 0}, {40, 8.8}, {0, 8.8}}, {}, "channel 8.8 x 40").value();
  const Pocket l = scaled(load("l_pocket_islands.json"), 0.6);
  for (const auto& [p, tool_d] : {std::pair{l, 8.0}, std::pair{channel, 8.0}}) {
    AdaptiveParams ap;
    ap.stepover_mm = 1.6;
    ap.depth_mm = 6.0;
    ap.stepdown_mm = 2.0;
    auto r = adaptive_pocket(p, flat_mill(tool_d), ap);
    ASSERT_TRUE(r.ok()) << r.status().to_string();
    const auto& mv = r->toolpath.moves;
    int entries = 0, first_layer = 0;
    for (std::size_t k = 1; k < mv.size(); ++k) {
      if (mv[k].kind != MoveKind::kHelix && mv[k].kind != MoveKind::kRamp) continue;
      if (mv[k - 1].kind == MoveKind::kHelix || mv[k - 1].kind == MoveKind::kRamp) continue;
      ++entries;
      const double start_z = mv[k - 1].end.z;
      // The layer this entry descends to, and the floor of the one before it.
      double z_to = mv[k].end.z;
      for (std::size_t q = k;
           q < mv.size() && (mv[q].kind == MoveKind::kHelix || mv[q].kind == MoveKind::kRamp); ++q)
        z_to = mv[q].end.z;
      const double floor_before = z_to + 2.0;  // stepdown 2, from the top at 0
      if (floor_before >= -1e-9) {
        ++first_layer;
        EXPECT_NEAR(start_z, 1.0, 1e-9) << p.source;
      } else {
        EXPECT_LE(start_z, floor_before + 1e-9) << p.source << " entry to " << z_to;
      }
    }
    EXPECT_GE(entries, 3) << p.source;  // one a layer at least
    EXPECT_GE(first_layer, 1) << p.source;
    const auto s = testing::sweep_check(p.region, 0.5 * tool_d, r->toolpath,
                                        r->target_engagement_deg, kCheckerPixel, kWallTol);
    EXPECT_LE(s.max_gouge_mm, 1e-6);
  }
}

// The same in a straight channel: a ø10 beside an island 10.05 mm from the wall (0.025 mm of
// room each side). The channel's middle is reached from nowhere else; it was left whole
// (127 mm^2 by the sweep). Whether a row of pixel centres falls inside the 0.05 mm strip of
// free centres turns on the pixel: with none, straight plunges take the channel; with one,
// the passes reach it and the neck plunges go through it. Either way it is plunged, not
// left and not slotted.
TEST(AdaptivePocket, ChannelAHairWiderThanTheToolIsTakenByPlunges) {
  const Pocket p =
      make_pocket({{0, 0}, {80, 0}, {80, 60}, {0, 60}},
                  {{{20, 20}, {69.95, 20}, {69.95, 40}, {20, 40}}}, "80 x 60, channel 10.05 mm")
          .value();
  const Outcome o = run(p, 10.0, 1.0);
  EXPECT_LE(o.sweep.max_gouge_mm, 1e-6);
  EXPECT_GE(o.result.straight_plunges + o.result.neck_plunges, 3);
  // The plunges' ends in the channel, 0.025 mm of room each side: full slots, read so since
  // session 49's sweep reads the arc up to both walls (0.67 mm).
  EXPECT_LE(o.sweep.slot_length_mm, 0.8);
  EXPECT_LE(o.sweep.residual_mm2, kResidualPerCornerMm2 * 8);
  // Every retract leaves the floor straight up. After a plunge the path's point there had
  // been snapped to the wall offset 0.02 mm away, and the rapid went sideways at the floor.
  const auto& mv = o.result.toolpath.moves;
  for (std::size_t k = 1; k < mv.size(); ++k) {
    if (mv[k].kind == MoveKind::kRapid && mv[k - 1].end.z < 0.0) {
      EXPECT_EQ(mv[k].end.x, mv[k - 1].end.x) << "move " << k;
      EXPECT_EQ(mv[k].end.y, mv[k - 1].end.y) << "move " << k;
    }
  }
}

// A round chamber 0.1 mm wider than the tool, behind a neck half as wide as the tool (found
// by bench/pocket_random.sh, seed 118: 28.6 mm^2 left, a whole disk). No helix or ramp fits
// in it and no cleared floor leads there; the default goes straight down into it, and the
// sweep finds nothing left that the tool reaches. Turned off, the chamber is left, and the
// summary's material_left says so.
TEST(AdaptivePocket, ChamberWithNoRoomToHelixIsEnteredStraightDown) {
  const double cr = 3.1, cx = 43.0 + cr, half_neck = 1.5;
  const double a0 = std::atan2(-half_neck, -std::sqrt(cr * cr - half_neck * half_neck));
  Ring outer{{0, 0}, {40, 0}, {40, 15 - half_neck}};
  for (int k = 0; k <= 240; ++k) {               // the chamber's far side, counter-clockwise
    const double a = a0 - 2.0 * a0 * k / 240.0;  // from a0 (about -150 deg) to -a0
    outer.push_back({cx + cr * std::cos(a), 15 + cr * std::sin(a)});
  }
  outer.insert(outer.end(), {{40, 15 + half_neck}, {40, 30}, {0, 30}});
  const Pocket p = make_pocket(outer, {}, "rectangle and chamber").value();
  const Outcome o = run(p, 6.0, 0.6);
  EXPECT_EQ(o.result.straight_plunges, 1);
  expect_correct(p, o, -1.0);
  Tool t;
  t.diameter_mm = 6.0;
  AdaptiveParams off;
  off.stepover_mm = 0.6;
  off.depth_mm = 3.0;
  off.straight_plunge = false;
  auto left = adaptive_pocket(p, t, off);
  ASSERT_TRUE(left.ok()) << left.status().to_string();
  EXPECT_EQ(left->straight_plunges, 0);
  EXPECT_GT(left->material_left_mm2, 20.0);  // the chamber: about pi 3.1^2 = 30 mm^2
}

// A pocket too large for its tool at the resolution rule's pixel size (a 250 mm square cut
// with a 3 mm end mill needs about 90 million pixels): the automatic resolution is coarsened
// to the pixel budget, and the path is still correct by the independent sweep. A small
// pocket with a small budget stands for the large case here.
TEST(AdaptivePocket, PocketTooLargeForThePixelBudgetCoarsensTheResolution) {
  const Pocket p =
      make_pocket({{0, 0}, {30, 0}, {30, 20}, {0, 20}}, {{{12, 7}, {18, 7}, {18, 13}, {12, 13}}},
                  "30 x 20 with a square island")
          .value();
  Tool t;
  t.diameter_mm = 2.0;
  AdaptiveParams ap;
  ap.stepover_mm = 0.2;
  ap.depth_mm = 3.0;
  // The rule (docs/pocket.md): the step a quarter of the stepover within [D / 40, D / 20]
  // = 0.05 mm, the pixel min(sqrt(stepover x step / 64), R / 40) = 0.0125 mm, about 4.6
  // million pixels here.
  const double step_mm = std::clamp(0.25 * 0.2, 2.0 / 40.0, 2.0 / 20.0);
  const double rule_mm = std::min(std::sqrt(0.2 * step_mm / 64.0), 1.0 / 40.0);
  ap.max_pixels = 1.5e6;
  auto coarse = adaptive_pocket(p, t, ap);
  ASSERT_TRUE(coarse.ok()) << coarse.status().to_string();
  const double h = coarse->resolution_mm;
  EXPECT_GT(h, 1.5 * rule_mm);
  EXPECT_DOUBLE_EQ(coarse->rule_resolution_mm, rule_mm);  // reported, so users can tell
  const double margin = 1.0 + step_mm + 4.0 * h;  // tool radius, step, four pixels (make_model)
  EXPECT_LE((std::ceil((30 + 2 * margin) / h) + 1) * (std::ceil((20 + 2 * margin) / h) + 1), 1.5e6);
  const auto s = testing::sweep_check(p.region, 1.0, coarse->toolpath,
                                      coarse->target_engagement_deg, 0.05, 0.1);
  std::printf("  coarsened to %.4f mm (rule %.4f): residual %.3f mm2, within20 %.1f %%\n", h,
              rule_mm, s.residual_mm2, 100 * s.within_20pct);
  EXPECT_LE(s.max_gouge_mm, 1e-6);
  EXPECT_LE(s.residual_mm2, kResidualPerCornerMm2 * 4);
  EXPECT_GE(s.within_20pct, 0.90);
  EXPECT_EQ(s.slot_length_mm, 0.0);
  // Too small a budget for any acceptable pixel (20 across the tool radius, 16 per step):
  // a named error, nothing generated.
  ap.max_pixels = 2e5;
  auto none = adaptive_pocket(p, t, ap);
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.status().code(), Error::kBadParameter);
  EXPECT_NE(none.status().to_string().find("pixel budget"), std::string::npos)
      << none.status().to_string();
  // An explicit resolution is never changed: over the budget it is an error too.
  ap.max_pixels = 1.5e6;
  ap.resolution_mm = rule_mm;
  auto fixed = adaptive_pocket(p, t, ap);
  ASSERT_FALSE(fixed.ok());
  EXPECT_NE(fixed.status().to_string().find("max_pixels"), std::string::npos)
      << fixed.status().to_string();
}

void expect_same_moves(const AdaptiveResult& a, const AdaptiveResult& b) {
  ASSERT_EQ(a.toolpath.moves.size(), b.toolpath.moves.size());
  for (std::size_t k = 0; k < a.toolpath.moves.size(); ++k)
    ASSERT_EQ(a.toolpath.moves[k].end, b.toolpath.moves[k].end) << "move " << k;
}

TEST(AdaptivePocket, SameInputSameToolpath) {
  const Pocket p = load("kirimoto_pocket.json");
  auto a = generate(p, 10.0, 2.0);
  auto b = generate(p, 10.0, 2.0);
  ASSERT_TRUE(a.ok() && b.ok());
  expect_same_moves(*a, *b);
}

// seed 000 4.1: several plunge points along the medial axis, the fastest path kept. The
// candidates are simulated in parallel; the choice and the path must not depend on it.
TEST(AdaptivePocket, PlungeCandidatesKeepTheFastestWhateverTheThreads) {
  const Pocket p = load("kirimoto_pocket.json");
  Tool t;
  t.diameter_mm = 10.0;
  AdaptiveParams ap;
  ap.stepover_mm = 2.0;
  ap.depth_mm = 3.0;
  auto single = adaptive_pocket(p, t, ap);  // the first candidate alone
  ap.plunge_candidates = 4;
  Context one, two;
  one.threads = 1;
  two.threads = 2;
  auto a = adaptive_pocket(p, t, ap, one);
  auto b = adaptive_pocket(p, t, ap, two);
  ASSERT_TRUE(single.ok() && a.ok() && b.ok());
  ASSERT_EQ(a->candidate_time_s.size(), 4u);
  ASSERT_EQ(a->candidate_plunge_points.size(), 4u);
  // Kept: the least time, the first one on a tie.
  const auto fastest = std::min_element(a->candidate_time_s.begin(), a->candidate_time_s.end());
  EXPECT_EQ(a->chosen_candidate, fastest - a->candidate_time_s.begin());
  EXPECT_EQ(a->plunge_point,
            a->candidate_plunge_points[static_cast<std::size_t>(a->chosen_candidate)]);
  // The first candidate is what a single-candidate run computes, to the bit.
  ASSERT_EQ(single->candidate_time_s.size(), 1u);
  EXPECT_EQ(a->candidate_time_s[0], single->candidate_time_s[0]);
  EXPECT_EQ(a->candidate_plunge_points[0], single->plunge_point);
  // Distinct plunge points, each where the tool fits (clear of every wall by its radius).
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec2 c = a->candidate_plunge_points[i];
    double clearance = 1e300;
    for (const Ring& ring : p.region.rings) {
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const Vec2 u = ring[k], v = ring[(k + 1) % ring.size()];
        const double l = std::clamp(dot(c - u, v - u) / norm_sq(v - u), 0.0, 1.0);
        clearance = std::min(clearance, distance(c, u + (v - u) * l));
      }
    }
    EXPECT_GE(clearance, 0.5 * t.diameter_mm) << "candidate " << i;
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_GT(distance(c, a->candidate_plunge_points[j]), 1.0) << i << " and " << j;
  }
  // Same choice and same moves with one thread or two.
  EXPECT_EQ(a->candidate_time_s, b->candidate_time_s);
  EXPECT_EQ(a->chosen_candidate, b->chosen_candidate);
  expect_same_moves(*a, *b);
}

TEST(AdaptivePocket, StepoverAndEngagementAngleAreTheSameParameter) {
  // acos(1 - stepover / R): 10 % of a 10 mm tool is 36.87 degrees.
  EXPECT_NEAR(engagement_angle_deg(1.0, 5.0), rad_to_deg(std::acos(0.8)), 1e-12);
  EXPECT_NEAR(stepover_for_angle_mm(engagement_angle_deg(1.3, 5.0), 5.0), 1.3, 1e-12);
}

}  // namespace
}  // namespace swarf
