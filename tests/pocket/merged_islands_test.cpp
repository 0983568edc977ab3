// Islands that overlap each other or reach the outer boundary (a boss drawn across the wall,
// two bosses drawn as overlapping squares, a rib right across the pocket): make_pocket
// merges them, the pocket being the outer ring's inside minus their union, and the adaptive
// pocket clears every part it leaves. Judged against regions built here by hand.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "cli/cli_test_util.h"
#include "pocket/adaptive_test_util.h"
#include "pocket/sweep_checker.h"
#include "swarf/gcode/gcode.h"
#include "swarf/pocket/adaptive.h"
#include "swarf/pocket/pocket_input.h"

namespace swarf {
namespace {

Ring rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

bool says(const std::vector<std::string>& notes, const std::string& what) {
  for (const std::string& n : notes)
    if (n.find(what) != std::string::npos) return true;
  return false;
}

TEST(MergedIslands, AnIslandAcrossTheWallBecomesANotchInIt) {
  auto p = make_pocket(rect(0, 0, 50, 40), {rect(40, 10, 60, 20)}, "cross.json");
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  EXPECT_NEAR(area(p->region), 50.0 * 40.0 - 10.0 * 10.0, 1e-6);
  EXPECT_EQ(p->region.rings.size(), 1u);
  EXPECT_EQ(p->island_count(), 0u);
  EXPECT_TRUE(says(p->notes, "cross.json: island 1 crosses or touches the outer boundary"));
  // Touching along an edge is the same case.
  auto t = make_pocket(rect(0, 0, 50, 40), {rect(0, 10, 10, 20)}, "touch.json");
  ASSERT_TRUE(t.ok()) << t.status().to_string();
  EXPECT_NEAR(area(t->region), 50.0 * 40.0 - 10.0 * 10.0, 1e-6);
}

TEST(MergedIslands, OverlappingIslandsBecomeOne) {
  auto p =
      make_pocket(rect(0, 0, 50, 40), {rect(10, 10, 25, 25), rect(20, 20, 30, 30)}, "two.json");
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  EXPECT_NEAR(area(p->region), 2000.0 - (225.0 + 100.0 - 25.0), 1e-6);
  EXPECT_EQ(p->island_count(), 1u);
  EXPECT_TRUE(says(p->notes, "islands 1 and 2 overlap or touch"));
}

TEST(MergedIslands, IslandsThatDivideThePocketLeaveEachPart) {
  auto p = make_pocket(rect(0, 0, 50, 40), {rect(20, -5, 30, 45)}, "rib.json");
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  ASSERT_EQ(p->region.rings.size(), 2u);
  for (const Ring& r : p->region.rings)
    EXPECT_NEAR(signed_area(r), 20.0 * 40.0, 1e-6);  // two outer rings, counter-clockwise
  EXPECT_TRUE(says(p->notes, "2 separate areas"));
}

TEST(MergedIslands, WhatIsNotAPocketIsStillRejected) {
  // An island crossing the wall and itself.
  auto bow = make_pocket(rect(0, 0, 50, 40), {{{40, 10}, {60, 20}, {60, 10}, {40, 20}}}, "b.json");
  ASSERT_FALSE(bow.ok());
  EXPECT_NE(bow.status().message().find("island 1 intersects itself"), std::string::npos)
      << bow.status().message();
  // Wholly outside, wholly inside another island: no touch, no merge (a drawing mistake or
  // a pocket inside a boss, which needs its own job).
  auto out = make_pocket(rect(0, 0, 50, 40), {rect(60, 10, 70, 20)}, "o.json");
  ASSERT_FALSE(out.ok());
  EXPECT_NE(out.status().message().find("lies outside"), std::string::npos);
  auto nested =
      make_pocket(rect(0, 0, 50, 40), {rect(10, 10, 35, 30), rect(15, 15, 20, 20)}, "n.json");
  ASSERT_FALSE(nested.ok());
  EXPECT_NE(nested.status().message().find("island 2 lies inside island 1"), std::string::npos);
  auto all = make_pocket(rect(0, 0, 50, 40), {rect(0, 0, 50, 40)}, "a.json");
  ASSERT_FALSE(all.ok());
  EXPECT_NE(all.status().message().find("cover the whole pocket"), std::string::npos);
}

// A drawing's loops have no roles but their sizes: loops inside the outline that overlap
// or touch it are bosses and merged; a loop crossing the outline (partly outside) may be
// part of the pocket as well as a boss, and is refused rather than guessed.
TEST(MergedIslands, DrawingsMergeLoopsInsideAndRefuseLoopsAcrossTheOutline) {
  auto inside = parse_pocket_svg(
      R"(<svg><rect x="0" y="0" width="50" height="40"/><rect x="10" y="10" width="15" height="15"/>)"
      R"(<rect x="20" y="20" width="10" height="10"/><rect x="40" y="5" width="10" height="10"/></svg>)",
      "in.svg");
  ASSERT_TRUE(inside.ok()) << inside.status().to_string();
  EXPECT_NEAR(area(inside->region), 2000.0 - (225.0 + 100.0 - 25.0) - 100.0, 1e-6);
  EXPECT_TRUE(says(inside->notes, "island 3 crosses or touches the outer boundary"));
  auto across = parse_pocket_svg(
      R"(<svg><rect x="0" y="0" width="50" height="40"/><rect x="40" y="5" width="20" height="10"/></svg>)",
      "across.svg");
  ASSERT_FALSE(across.ok());
  EXPECT_EQ(across.status().code(), Error::kBadInput);
  EXPECT_NE(across.status().message().find("across.svg: island 1 (a closed loop of the drawing) "
                                           "crosses the outer boundary"),
            std::string::npos)
      << across.status().message();
}

// Clears `region` (built by hand) from the pocket made of `outer` and `islands`: no gouge by
// exact distances, nothing reachable left but a few checker pixels per corner.
void expect_cleared(const Ring& outer, const std::vector<Ring>& islands, const PolygonSet& region,
                    double max_residual_mm2) {
  auto p = make_pocket(outer, islands, "merged.json");
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  auto r = adaptive_pocket(*p, testing::flat_mill(6.0), testing::params_3mm_deep(1.0));
  ASSERT_TRUE(r.ok()) << r.status().to_string();
  const auto s =
      testing::sweep_check(region, 3.0, r->toolpath, r->target_engagement_deg, 0.08, 0.25);
  std::printf("  gouge %.4f mm, residual %.2f mm2, cutting %.0f mm, within20 %.1f %%\n",
              s.max_gouge_mm, s.residual_mm2, s.cutting_length_mm, 100 * s.within_20pct);
  EXPECT_LE(s.max_gouge_mm, 1e-6);
  EXPECT_LE(s.residual_mm2, max_residual_mm2);
  EXPECT_EQ(s.slot_length_mm, 0.0);
}

TEST(MergedIslands, BothSidesOfARibAcrossThePocketAreCleared) {
  const PolygonSet sides{{rect(0, 0, 20, 40), rect(30, 0, 50, 40)}};
  expect_cleared(rect(0, 0, 50, 40), {rect(20, -5, 30, 45)}, sides, 8 * 0.1);
}

// Each area's entry hole is an entry's in the report's cut map (2), as the first area's: the
// later one's showed as a cut of no engagement (blue in the picture).
TEST(MergedIslands, EachAreasEntryHoleIsAnEntryInTheCutMap) {
  auto p = make_pocket(rect(0, 0, 50, 40), {rect(20, -5, 30, 45)}, "rib.json");
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  auto r = adaptive_pocket(*p, testing::flat_mill(6.0), testing::params_3mm_deep(1.0));
  ASSERT_TRUE(r.ok()) << r.status().to_string();
  const CutMap& map = r->cut_map;
  int left = 0, right = 0;  // entry cells either side of the rib
  for (int j = 0; j < map.height; ++j)
    for (int i = 0; i < map.width; ++i) {
      if (map.cells[static_cast<std::size_t>(j) * map.width + i] != 2u) continue;
      (map.origin.x + i * map.pixel_mm < 25.0 ? left : right) += 1;
    }
  // Each hole is at least the tool's disk: 28 mm^2.
  const double disk_px = 3.14159 * 3.0 * 3.0 / (map.pixel_mm * map.pixel_mm);
  EXPECT_GT(left, disk_px);
  EXPECT_GT(right, disk_px);
}

// Without the cut map (the CLI asks for it only with --report) the path, the steps'
// engagement and the material left are the same to the bit and the map is left empty; with
// it, the map covers the pocket (its non-zero cells hold at least 90 % of the pocket's area).
TEST(MergedIslands, TheCutMapIsOptionalAndChangesNothingElse) {
  auto p = make_pocket(rect(0, 0, 50, 40), {rect(20, -5, 30, 45)}, "rib.json");
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  AdaptiveParams with = testing::params_3mm_deep(1.0);
  AdaptiveParams without = with;
  without.cut_map = false;
  auto a = adaptive_pocket(*p, testing::flat_mill(6.0), with);
  auto b = adaptive_pocket(*p, testing::flat_mill(6.0), without);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_TRUE(b->cut_map.cells.empty());
  EXPECT_EQ(b->cut_map.width, 0);
  ASSERT_EQ(a->cut_map.cells.size(), static_cast<std::size_t>(a->cut_map.width) *
                                         static_cast<std::size_t>(a->cut_map.height));
  std::size_t pocket_cells = 0;
  for (std::uint32_t c : a->cut_map.cells)
    pocket_cells += c != 0u ? 1 : 0;
  EXPECT_GT(static_cast<double>(pocket_cells) * a->cut_map.pixel_mm * a->cut_map.pixel_mm,
            0.9 * (50.0 * 40.0 - 10.0 * 40.0));
  GcodeOptions o;
  const Toolpath ta[] = {a->toolpath}, tb[] = {b->toolpath};
  EXPECT_EQ(write_gcode(ta, o), write_gcode(tb, o));
  ASSERT_EQ(a->steps.size(), b->steps.size());
  for (std::size_t k = 0; k < a->steps.size(); ++k)
    ASSERT_EQ(a->steps[k].engagement_px, b->steps[k].engagement_px) << "step " << k;
  EXPECT_EQ(a->material_left_mm2, b->material_left_mm2);
}

TEST(MergedIslands, OverlappingIslandsAreCutRoundAsOne) {
  // The union of the two squares, clockwise: an island.
  const Ring both = {{10, 10}, {10, 25}, {20, 25}, {20, 30},
                     {30, 30}, {30, 20}, {25, 20}, {25, 10}};
  const PolygonSet region{{rect(0, 0, 50, 40), both}};
  expect_cleared(rect(0, 0, 50, 40), {rect(10, 10, 25, 25), rect(20, 20, 30, 30)}, region, 4 * 0.1);
}

// The command line says what it merged, and the G-code it writes sweeps clean.
TEST(MergedIslands, TheCommandLineSaysWhatItMerged) {
  testing::TempDir dir;
  const std::string in = dir.file("boss.json");
  dir.write("boss.json", R"({"outer": [[0,0],[50,0],[50,40],[0,40]],
                              "islands": [[[40,10],[60,10],[60,20],[40,20]]]})");
  const auto r = testing::run_swarf("pocket " + in + " --tool flat:6 --stepover 1 --depth 3 -o " +
                                    dir.file("out.nc"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("note: " + in + ": island 1 crosses or touches the outer boundary"),
            std::string::npos)
      << r.out;
  auto tp = read_gcode(dir.file("out.nc"));
  ASSERT_TRUE(tp.ok()) << tp.status().to_string();
  const Ring notched = {{0, 0}, {50, 0}, {50, 10}, {40, 10}, {40, 20}, {50, 20}, {50, 40}, {0, 40}};
  const auto s = testing::sweep_check(PolygonSet{{notched}}, 3.0, *tp, 48.19, 0.1, 0.3);
  EXPECT_LE(s.max_gouge_mm, 0.005);  // the G-code's 4 decimals
  EXPECT_LE(s.residual_mm2, 6 * 0.1);
}

}  // namespace
}  // namespace swarf
