// Necks barely wider than the tool: the path plunges through them in crescents instead of
// cutting a full slot (neck_plunges.cpp), judged by the independent sweep.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "pocket/adaptive_internal.h"
#include "pocket/adaptive_test_util.h"
#include "pocket/sweep_checker.h"
#include "swarf/pocket/adaptive.h"
#include "swarf/pocket/pocket_input.h"

namespace swarf {
namespace {

// A cut 94 % of the diameter wide or more: the whole front of the tool in the material.
// Through a neck 0.1 mm wider than the tool every pass is one, but not always a full slot
// by the sweep's 170 degrees: that turns on where the pass lies between the walls, which
// turns on the pixel (passes zig-zagging between the two walls' offsets read 145-165
// degrees, before such points went to the channel's middle).
constexpr double kHeavyDeg = 140.0;

struct Cut {
  AdaptiveResult result;
  testing::SweepReport sweep;
  double heavy_mm = 0.0;  ///< by the sweep, outside the entry
};

Cut cut(bool plunge) {
  const Pocket p = testing::dumbbell_pocket();
  AdaptiveParams ap = testing::params_3mm_deep(1.0);
  ap.depth_mm = 6.0;
  ap.straight_plunge = plunge;
  auto r = adaptive_pocket(p, testing::flat_mill(10.0), ap);
  EXPECT_TRUE(r.ok()) << r.status().to_string();
  Cut c{r.value(), {}};
  std::vector<testing::SweepSample> samples;
  c.sweep = testing::sweep_check(p.region, 5.0, c.result.toolpath, c.result.target_engagement_deg,
                                 0.05, 0.2, &samples);
  for (const testing::SweepSample& q : samples)
    if (q.engagement_deg >= kHeavyDeg) c.heavy_mm += q.length_mm;
  std::printf(
      "  plunge %d: slot %.1f mm, heavy %.1f mm, gouge %.4f mm, residual %.2f mm2, neck "
      "plunges %d\n",
      plunge, c.sweep.slot_length_mm, c.heavy_mm, c.sweep.max_gouge_mm, c.sweep.residual_mm2,
      c.result.neck_plunges);
  return c;
}

// Heavy cuts in the path's steps: plunged through, and cut as passes.
std::pair<double, double> report_heavy_mm(const AdaptiveResult& r, double min_deg = kHeavyDeg) {
  double plunged = 0.0, cut = 0.0;
  for (const AdaptiveStep& st : r.steps)
    if (st.kind != StepKind::kLink && st.engagement_deg >= min_deg)
      (st.plunged ? plunged : cut) += st.length_mm;
  return {plunged, cut};
}

TEST(NeckPlunges, ANeckAsWideAsTheToolIsPlungedThroughNotSlotted) {
  const Cut slotted = cut(false);
  EXPECT_GT(slotted.heavy_mm, 3.0);  // what the neck costs without the plunges
  EXPECT_EQ(slotted.result.neck_plunges, 0);
  const Cut plunged = cut(true);
  // The report says what the output does: the steps of a neck plunged through are "neck"
  // in the per-step CSV and out of the summary's cutting length and engagement figures
  // (before, both counted them as the full slot the pass would have been, while the G-code
  // and the sweep had the plunges). Without the plunges they are cuts, the slot among them.
  AdaptiveParams ap = testing::params_3mm_deep(1.0);
  ap.depth_mm = 6.0;
  const auto [slotted_plunged_mm, slotted_cut_mm] = report_heavy_mm(slotted.result);
  EXPECT_EQ(slotted_plunged_mm, 0.0);
  EXPECT_GT(slotted_cut_mm, 3.0);
  EXPECT_EQ(summarize(slotted.result, ap).plunged_length_mm, 0.0);
  EXPECT_EQ(steps_csv(slotted.result).find(",neck,"), std::string::npos);
  // Plunged through, with no full slot left among the cuts; the approaches into the neck's
  // two mouths still read heavy (140-160 degrees over a few tenths of a millimetre).
  const auto [plunged_mm, cut_mm] = report_heavy_mm(plunged.result);
  EXPECT_GT(plunged_mm, 3.0);
  EXPECT_LE(cut_mm, 1.0);
  EXPECT_EQ(report_heavy_mm(plunged.result, 170.0).second, 0.0);
  // The summary's plunged length is the CSV's `neck` rows (lengths to 4 decimals).
  const std::string csv = steps_csv(plunged.result);
  double neck_rows_mm = 0.0;
  int neck_rows = 0;
  for (std::size_t at = csv.find(",neck,"); at != std::string::npos;
       at = csv.find(",neck,", at + 1)) {
    const std::size_t eol = csv.find('\n', at), last = csv.rfind(',', eol) + 1;
    neck_rows_mm += std::stod(csv.substr(last, eol - last));
    ++neck_rows;
  }
  EXPECT_GT(neck_rows_mm, 3.0);
  EXPECT_NEAR(summarize(plunged.result, ap).plunged_length_mm, neck_rows_mm,
              5e-5 * neck_rows + 1e-9);
  EXPECT_LE(plunged.sweep.slot_length_mm, 0.3);
  EXPECT_LE(plunged.heavy_mm, 0.15 * slotted.heavy_mm);
  EXPECT_GT(plunged.result.neck_plunges, 0);
  EXPECT_LE(plunged.sweep.max_gouge_mm, 1e-6);
  EXPECT_LE(plunged.sweep.residual_mm2, slotted.sweep.residual_mm2 + 0.05);
  // Each plunge in a neck is a crescent: its centre within half a radius of the last hole
  // or, for a neck's first, of where the tool rose from the floor, so the tool's centre is
  // over cut space. (The entry's helix is not a plunge move, and the plunge back down after
  // a retract, into space already cut, is not a cutting one: every cutting kPlunge here is
  // in a neck.)
  const std::vector<Move>& mv = plunged.result.toolpath.moves;
  const double floor_z = -6.0;
  int plunges = 0;
  Vec2 last_cut{1e9, 1e9};
  for (std::size_t k = 1; k < mv.size(); ++k) {
    if (mv[k].kind == MoveKind::kPlunge && mv[k].cutting) {
      ++plunges;
      EXPECT_LE(distance(mv[k].end.xy(), last_cut), 0.5 * 5.0 + 1e-6) << "move " << k;
    }
    if (std::abs(mv[k].end.z - floor_z) < 1e-9) last_cut = mv[k].end.xy();
  }
  EXPECT_EQ(plunges, plunged.result.neck_plunges);
}

// The model of a ø20 in a dumbbell of two chambers whose neck is 21 mm wide (x 50-70, y
// 15-36): half a millimetre of room each side, within reach of the rules for heavy cuts
// between close walls (a millimetre) but more than the four pixels under which a heavy cut
// is a slot by itself (AHeavyCutWithUnderFourPixelsOfRoomIsASlot).
Result<pocket::Model> dumbbell_20_model() {
  const Pocket p = make_pocket({{0, 0},
                                {50, 0},
                                {50, 15},
                                {70, 15},
                                {70, 0},
                                {120, 0},
                                {120, 50},
                                {70, 50},
                                {70, 36.0},
                                {50, 36.0},
                                {50, 50},
                                {0, 50}},
                               {}, "dumbbell 20")
                       .value();
  return pocket::make_model(p, testing::flat_mill(20.0), testing::params_3mm_deep(3.0));
}

// Output moves for pocket::neck_runs, a point at a time: each move runs from the last point
// to the new one and removes `deg` by the model.
struct KeptPath {
  pocket::LinkedPath lp;
  std::vector<std::size_t> keep;
  std::vector<pocket::KeptMove> kept = std::vector<pocket::KeptMove>(1);

  void add(Vec2 at, double deg, bool link = false, bool jump = false, bool out_of_hole = false) {
    if (!lp.pts.empty()) {
      lp.kind.push_back(link ? StepKind::kLink : StepKind::kCut);
      lp.jump.push_back(jump);
      lp.entry.push_back(-1);
      pocket::KeptMove km;
      km.len = distance(lp.pts.back(), at);
      km.deg = deg;
      km.link = link;
      km.fast = link;
      km.out_of_hole = out_of_hole;
      kept.push_back(km);
    }
    keep.push_back(lp.pts.size());
    lp.pts.push_back(at);
  }
  std::vector<pocket::NeckRun> runs(const pocket::Model& m) const {
    return pocket::neck_runs(m, lp, keep, kept);
  }
};

// Which runs of output moves count as a neck's slot (pocket::neck_runs), on the model of a
// ø20 in a dumbbell whose neck is 21 mm wide (random pocket 1088's was 20.08 mm, where the
// model's removal read 145-165 degrees and the sweep saw a full slot; such a neck is narrow
// now, AHeavyCutWithUnderFourPixelsOfRoomIsASlot).
TEST(NeckPlunges, RunsAreFullSlotsOrHeavyCutsBetweenCloseWalls) {
  auto m = dumbbell_20_model();
  ASSERT_TRUE(m.ok()) << m.status().to_string();
  // `count` moves of 0.5 mm along y = y0 from x = x0, each removing `deg` by the model.
  auto runs = [&](double x0, double y0, int count, double deg) {
    KeptPath path;
    for (int k = 0; k <= count; ++k)
      path.add({x0 + 0.5 * k, y0}, deg);
    return path.runs(*m);
  };
  const double axis = 25.5;  // the neck's axis; the tool has 0.5 mm each side
  const auto neck = runs(52.0, axis, 20, 130.0);
  ASSERT_EQ(neck.size(), 1u);
  EXPECT_EQ(neck[0].first, 1u);
  EXPECT_EQ(neck[0].last, 20u);
  EXPECT_DOUBLE_EQ(neck[0].length_mm, 10.0);
  EXPECT_TRUE(runs(52.0, axis, 20, 100.0).empty());   // a lighter cut is cut as it is
  EXPECT_TRUE(runs(52.0, axis, 1, 130.0).empty());    // 0.5 mm: a loop of a trochoid
  EXPECT_TRUE(runs(15.0, axis, 20, 130.0).empty());   // the same cut in a chamber
  EXPECT_EQ(runs(15.0, axis, 20, 165.0).size(), 1u);  // a full slot anywhere
  EXPECT_EQ(runs(15.0, axis, 1, 165.0).size(), 1u);   // however short, from 0.2 mm
  // One long move from before the neck's mouth into it (random pocket 1130: a boundary move
  // began 0.75 mm before a channel and ran 7.7 mm in it, 7.4 mm of slot by the sweep): the
  // neck when the walls close in on it over at least half its length, whichever end.
  auto one_move = [&](Vec2 a, Vec2 b, double deg) {
    pocket::LinkedPath lp;
    lp.pts = {a, b};
    lp.kind = {StepKind::kBoundary};
    lp.jump = {false};
    lp.entry = {-1};
    std::vector<pocket::KeptMove> kept(2);
    kept[1].len = distance(a, b);
    kept[1].deg = deg;
    kept[1].link = false;
    kept[1].fast = false;
    return pocket::neck_runs(*m, lp, {0, 1}, kept);
  };
  EXPECT_EQ(one_move({46.0, axis}, {58.0, axis}, 130.0).size(), 1u);  // 8 mm of 12 in it
  EXPECT_EQ(one_move({74.0, axis}, {62.0, axis}, 130.0).size(), 1u);  // out at the far end
  EXPECT_TRUE(one_move({40.0, axis}, {52.0, axis}, 130.0).empty());   // 2 mm of 12
}

// A creep through a channel a few tenths wider than the tool (random pocket 1516: a ø8
// between a round island and the wall 8.1-8.25 mm apart): heavy cuts of a step or two, each
// too short to count alone, with short moves back and links between. Pieces of slot less
// than a tool radius apart along the path, pinched between the walls all the way between,
// make one neck; not across a retract, not through a chamber, not farther apart.
TEST(NeckPlunges, PiecesOfACreepThroughANeckAreOneNeck) {
  auto m = dumbbell_20_model();
  ASSERT_TRUE(m.ok()) << m.status().to_string();
  const double axis = 25.5;
  // Two heavy cuts 0.6 mm each (a heavy run needs 1 mm), from x0 and from x0 + 0.6, with
  // the path in between: `gap` points after the first.
  struct Pt {
    double x, y;
    bool link, jump;
  };
  auto runs = [&](double x0, const std::vector<Pt>& gap) {
    KeptPath path;
    path.add({x0, axis}, 0.0);
    path.add({x0 + 0.6, axis}, 130.0);
    for (const Pt& g : gap)
      path.add({g.x, g.y}, 20.0, g.link, g.jump);
    path.add({x0 + 1.2, axis}, 130.0);
    return path.runs(*m);
  };
  // In the neck: back 0.3 mm, a link forward to where the first cut ended: one neck.
  const auto creep = runs(55.0, {{55.3, axis, false, false}, {55.6, axis, true, false}});
  ASSERT_EQ(creep.size(), 1u);
  EXPECT_EQ(creep[0].first, 1u);
  EXPECT_EQ(creep[0].last, 4u);
  EXPECT_NEAR(creep[0].length_mm, 1.2, 1e-12);
  // The same with a retract between (the cusps taken backwards would cross it at the floor).
  EXPECT_TRUE(runs(55.0, {{55.3, axis, false, true}, {55.6, axis, true, false}}).empty());
  // Between the pieces the path goes out of the neck's mouth into the chamber and back (8.8
  // mm, within a radius).
  EXPECT_TRUE(runs(51.0, {{47.0, axis, true, false}, {51.6, axis, true, false}}).empty());
  EXPECT_EQ(runs(51.0, {{50.5, axis, true, false}, {51.6, axis, true, false}}).size(), 1u);
  // In the neck, but 12 mm of path between the pieces (more than a radius).
  EXPECT_TRUE(runs(55.0, {{61.6, axis, true, false}, {55.6, axis, true, false}}).empty());
}

// A heavy move just past a neck's run (a short move back and a link between, in the neck)
// belongs to it when it reads 100 degrees or more by the model, though under the 110 of a
// heavy run: between walls this close the model misses the slivers beside the tool (random
// pocket 1516: 108 degrees by the model, 179 by the sweep). Not after a run too short to be
// a neck, not a lighter move, not past a retract.
TEST(NeckPlunges, AHeavyMoveJustPastANeckBelongsToIt) {
  auto m = dumbbell_20_model();
  ASSERT_TRUE(m.ok()) << m.status().to_string();
  const double axis = 25.5;
  // `count` heavy cuts of 0.5 mm at 130 degrees from x = 55, 0.3 mm back, a link forward,
  // then a move of 0.4 mm removing `deg`.
  auto runs = [&](int count, double deg, bool retract) {
    KeptPath path;
    for (int k = 0; k <= count; ++k)
      path.add({55.0 + 0.5 * k, axis}, k == 0 ? 0.0 : 130.0);
    const double end = 55.0 + 0.5 * count;
    path.add({end - 0.3, axis}, 20.0, false, retract);
    path.add({end, axis}, 0.0, true);
    path.add({end + 0.4, axis}, deg);
    return path.runs(*m);
  };
  const auto past = runs(3, 108.0, false);
  ASSERT_EQ(past.size(), 1u);
  EXPECT_EQ(past[0].first, 1u);
  EXPECT_EQ(past[0].last, 6u);
  EXPECT_NEAR(past[0].length_mm, 1.5 + 0.3 + 0.3 + 0.4, 1e-12);
  // A lighter move stays out of the neck, which ends where its heavy run does.
  const auto lighter = runs(3, 95.0, false);
  ASSERT_EQ(lighter.size(), 1u);
  EXPECT_EQ(lighter[0].last, 3u);
  // After a single heavy move (0.5 mm, short of the millimetre of a run), no neck at all.
  EXPECT_TRUE(runs(1, 108.0, false).empty());
  // Past a retract, the move is not the neck's.
  const auto retracted = runs(3, 108.0, true);
  ASSERT_EQ(retracted.size(), 1u);
  EXPECT_EQ(retracted[0].last, 3u);
}

// The first move out of a straight plunge's hole into the material round it is a full slot
// however short (random pocket 1535: a ø10 tip visit 0.11 mm out of such a hole into a
// corner's tip read 135 degrees by the model, 180 by the sweep): plunged through from 110
// degrees, in the open chamber too. Not a lighter move, not the same move elsewhere.
TEST(NeckPlunges, AHeavyMoveOutOfAStraightPlungesHoleIsPlungedThrough) {
  auto m = dumbbell_20_model();
  ASSERT_TRUE(m.ok()) << m.status().to_string();
  auto runs = [&](double deg, bool out_of_hole) {
    KeptPath path;
    path.add({15.0, 25.0}, 0.0);
    path.add({14.89, 25.05}, deg, false, false, out_of_hole);
    path.add({15.0, 25.0}, 50.0);
    return path.runs(*m);
  };
  const auto tip = runs(135.0, true);
  ASSERT_EQ(tip.size(), 1u);
  EXPECT_EQ(tip[0].first, 1u);
  EXPECT_EQ(tip[0].last, 1u);
  EXPECT_NEAR(tip[0].length_mm, std::hypot(0.11, 0.05), 1e-12);
  EXPECT_TRUE(runs(105.0, true).empty());   // a lighter cut is cut as it is
  EXPECT_TRUE(runs(135.0, false).empty());  // elsewhere: too short for a run of its own
}

// A heavy cut where the room beside the tool is under four of the model's pixels (0.75 mm
// here) is a full slot from 0.2 mm, whichever way the walls lie about the move: at a
// channel's mouth the far wall is an island's corner ahead (random pocket 617: a ø20 crept
// 1.5 and 0.5 mm into the mouth of a channel 0.02 mm wider than itself, 143 and 134 degrees
// by the model, 170-177 by the sweep). Here a ø20 runs up the left wall (x = 0) towards the
// lower-left corner of a square island `gap` mm from it, its normal passing below the
// island.
TEST(NeckPlunges, AHeavyCutWithUnderFourPixelsOfRoomIsASlot) {
  auto runs = [](double gap, double y0, double length, double deg) {
    const Pocket p = make_pocket({{0, -40}, {60, -40}, {60, 40}, {0, 40}},
                                 {{{gap, 0}, {40, 0}, {40, 30}, {gap, 30}}}, "mouth")
                         .value();
    auto m = pocket::make_model(p, testing::flat_mill(20.0), testing::params_3mm_deep(3.0));
    EXPECT_TRUE(m.ok()) << m.status().to_string();
    if (!m.ok()) return std::vector<pocket::NeckRun>{};
    // Four pixels lie between the rooms tried: 0.03 mm (narrow) and 1 mm (not).
    EXPECT_GT(4.0 * m->h, 0.03);
    EXPECT_LT(4.0 * m->h, 1.0);
    KeptPath path;
    path.add({0.5 * gap, y0}, 0.0);
    path.add({0.5 * gap, y0 + length}, deg);
    return path.runs(*m);
  };
  const auto mouth = runs(20.03, -2.0, 1.5, 135.0);
  ASSERT_EQ(mouth.size(), 1u);
  EXPECT_EQ(mouth[0].first, 1u);
  EXPECT_EQ(mouth[0].last, 1u);
  EXPECT_EQ(runs(20.03, -1.0, 0.5, 135.0).size(), 1u);  // from 0.2 mm
  EXPECT_TRUE(runs(20.03, -1.0, 0.15, 135.0).empty());  // shorter: a pixel's misreading
  EXPECT_TRUE(runs(20.03, -2.0, 1.5, 105.0).empty());   // a lighter cut is cut as it is
  EXPECT_TRUE(runs(21.0, -2.0, 1.5, 135.0).empty());    // a millimetre of room
  EXPECT_TRUE(runs(20.03, -20.0, 1.5, 135.0).empty());  // along the wall, far from the island
}

}  // namespace
}  // namespace swarf
