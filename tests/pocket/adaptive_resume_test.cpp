// Where the adaptive path resumes once a front it was cutting runs out of cutting moves,
// judged by the independent sweep.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "pocket/adaptive_internal.h"
#include "pocket/adaptive_test_util.h"
#include "swarf/pocket/pocket_input.h"

namespace swarf {
namespace {

testing::SweptPath run(const std::string& file, double tool_d, double stepover_mm) {
  const Pocket p = testing::load_test_pocket(file);
  AdaptiveParams ap = testing::params_3mm_deep(stepover_mm);
  ap.depth_mm = 6.0;
  auto r = adaptive_pocket(p, testing::flat_mill(tool_d), ap);
  EXPECT_TRUE(r.ok()) << r.status().to_string();
  if (!r.ok()) return {};
  const testing::SweptPath out = testing::swept(p, tool_d, *r);
  std::printf("  %s: lifts %zu, machining %.0f s, within20 %.1f %%, residual %.2f mm2\n",
              file.c_str(), out.metrics.lift_offs, out.metrics.machining_time_s,
              100 * out.sweep.within_20pct, out.sweep.residual_mm2);
  return out;
}

// A channel a millimetre or two wider than the tool is cleared from its ends by crescents,
// one from each resume a step behind the front. The crescents leave slivers at the walls
// beside the front, and a resume point only half a step behind it still had a few of them
// in its disk: none was found near the front, the tool followed the boundary of the cut
// round to the channel's other front, and back, a crescent at each with a retract between
// (pocket 2446, a ring channel round a boss: 23 lifts and 167 s; pocket 1046, the two ends
// of a C-shaped region: 11 lifts and 173 s). Where only such crumbs hold the point back, a
// step or a step and a half behind the front is tried too. And the material at the front
// the tool has just cut from is not left given up (pocket 2440, channels 1.25 mm wider than
// a ø20 at 8 %: the material at both fronts had been given up by earlier sessions, no
// resume was looked for there, and the tool walked 50 to 60 mm from one front to the
// other 55 times: 11.6 m in the air and 270 s).
TEST(AdaptiveResume, AChannelIsClearedFromOneFrontAtATimeNotInTurns) {
  for (const auto& [file, d, so, most_lifts, most_s] :
       {std::tuple{"random_seed2446.json", 12.0, 3.6, 2U, 130.0},
        {"random_seed1046.json", 20.0, 6.0, 7U, 165.0},
        {"random_seed2440.json", 20.0, 1.6, 5U, 180.0}}) {
    const testing::SweptPath r = run(file, d, so);
    EXPECT_LE(r.metrics.lift_offs, most_lifts) << file;
    EXPECT_LE(r.metrics.machining_time_s, most_s) << file;
    EXPECT_LE(r.sweep.max_gouge_mm, 1e-6) << file;
    EXPECT_LE(r.sweep.residual_mm2, 0.5) << file;
    EXPECT_EQ(r.sweep.slot_length_mm, 0.0) << file;
  }
}

// A plate of nx x ny round islands ø6 at a 15 mm pitch, 9 mm from the walls and from each
// other: a ø10 passes between none of them, so its centres fall into separate chambers,
// one between each four islands and one between each two and the wall, each entered on its
// own.
Pocket plate_of_islands(int nx, int ny) {
  std::vector<Ring> islands;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      Ring ring;
      for (int k = 0; k < 24; ++k) {
        const double a = 2.0 * 3.141592653589793 * k / 24.0;
        ring.push_back({12.0 + 15.0 * i + 3.0 * std::cos(a), 12.0 + 15.0 * j + 3.0 * std::sin(a)});
      }
      islands.push_back(ring);
    }
  }
  const double w = 24.0 + 15.0 * (nx - 1), h = 24.0 + 15.0 * (ny - 1);
  return make_pocket({{0, 0}, {w, 0}, {w, h}, {0, h}}, islands, "plate of islands").value();
}

// Each chamber takes a dozen sessions (its entry, then resumes round its islands). The
// sessions were bounded at 200 in all, and every new entry made the crumbs of all the
// chambers before it resumable again: a plate of 4 x 3 islands kept 1321 mm^2 that the tool
// reaches (8 x 6: 7092 mm^2, and no note said so). Found in session 53.
TEST(AdaptiveResume, EveryChamberOfAPlateOfIslandsCloserThanTheToolIsCleared) {
  const Pocket p = plate_of_islands(4, 3);
  auto r = adaptive_pocket(p, testing::flat_mill(10.0), testing::params_3mm_deep(1.0));
  ASSERT_TRUE(r.ok()) << r.status().to_string();
  const testing::SweptPath s = testing::swept(p, 10.0, *r);
  std::printf("  plate 4 x 3: lifts %zu, residual %.2f mm2 (generator %.2f)\n", s.metrics.lift_offs,
              s.sweep.residual_mm2, r->material_left_mm2);
  EXPECT_LE(s.sweep.max_gouge_mm, 1e-6);
  EXPECT_LE(s.sweep.residual_mm2, 0.5);
  EXPECT_LE(r->material_left_mm2, 0.5);
  EXPECT_GE(s.metrics.lift_offs, 15U);  // a way into each chamber: they are apart
}

// Every pixel of the model's grid given up on.
pocket::BitImage all_given_up(const pocket::Model& m) {
  pocket::BitImage g(m.grid.width, m.grid.height);
  for (int j = 0; j < g.height(); ++j)
    g.set_span(j, 0, g.width() - 1);
  return g;
}

// Two rooms 30 x 30 joined by a neck 8 mm wide and 30 long, which a ø10 does not pass.
Pocket two_rooms() {
  return make_pocket({{0, 0},
                      {30, 0},
                      {30, 11},
                      {60, 11},
                      {60, 0},
                      {90, 0},
                      {90, 30},
                      {60, 30},
                      {60, 19},
                      {30, 19},
                      {30, 30},
                      {0, 30}},
                     {}, "two rooms")
      .value();
}

// After a new entry, the material given up on is tried again only where the entry's chamber
// (its component of free tool centres) can reach it: two rooms joined by a neck 8 mm wide,
// which a ø10 does not pass.
TEST(AdaptiveResume, ANewEntryRetriesOnlyWhatItsChamberReaches) {
  const Pocket two = two_rooms();
  auto m = pocket::make_model(two, testing::flat_mill(10.0), testing::params_3mm_deep(1.0));
  ASSERT_TRUE(m.ok()) << m.status().to_string();
  const pocket::CentreComponents cc = pocket::label_centre_components(*m);
  ASSERT_EQ(cc.size.size(), 2U);
  EXPECT_EQ(cc.size[0] + cc.size[1], cc.free);
  auto given_up_at = [&](const pocket::BitImage& g, Vec2 world) {
    const Vec2 q = m->grid.to_px(world);
    return g.get(static_cast<int>(std::lround(q.x)), static_cast<int>(std::lround(q.y)));
  };
  pocket::BitImage g = all_given_up(*m);
  pocket::forget_given_up_near(*m, cc, {15, 15}, g);
  EXPECT_FALSE(given_up_at(g, {15, 15}));  // the entry's room
  EXPECT_FALSE(given_up_at(g, {2, 2}));    // its corner, a tool radius from any centre
  EXPECT_TRUE(given_up_at(g, {75, 15}));   // the other room: nothing there has changed
  EXPECT_TRUE(given_up_at(g, {88, 28}));
  // An entry off the free pixel centres (a tight centre) retries everything, as before.
  pocket::BitImage off = all_given_up(*m);
  pocket::forget_given_up_near(*m, cc, {45, 15}, off);
  EXPECT_EQ(off.count_all(), 0U);
  // One room: all of it.
  const Pocket one = make_pocket({{0, 0}, {30, 0}, {30, 30}, {0, 30}}, {}, "one room").value();
  auto m1 = pocket::make_model(one, testing::flat_mill(10.0), testing::params_3mm_deep(1.0));
  ASSERT_TRUE(m1.ok());
  pocket::BitImage g1 = all_given_up(*m1);
  pocket::forget_given_up_near(*m1, pocket::label_centre_components(*m1), {15, 15}, g1);
  EXPECT_EQ(g1.count_all(), 0U);
}

// The block map that lets the resume search skip material far from any cleared floor,
// against a brute-force search: two rooms joined by a neck a ø10 does not pass, the first
// partly cut, the second untouched. Every material pixel for which some point on the ring
// (every 15 degrees, as the search tries) is a resume (no gouge, no material in its disk)
// lies in a set block, and the untouched room, even its corners and the pixels just inside
// its walls, does not.
TEST(AdaptiveResume, TheResumeSearchSkipsOnlyMaterialNoResumeReaches) {
  const Pocket two = two_rooms();
  for (const double wall_stock : {0.0, 0.5}) {
    AdaptiveParams ap = testing::params_3mm_deep(1.0);
    ap.wall_stock_mm = wall_stock;
    auto m = pocket::make_model(two, testing::flat_mill(10.0), ap);
    ASSERT_TRUE(m.ok()) << m.status().to_string();
    pocket::PixelStock stock = pocket::fresh_stock(*m);
    // The first room cleared but for a band 3 mm wide along its walls (tool centres over
    // [8, 22] x [9, 21] every 0.25 mm), then a ragged bite into the band by one move.
    for (int a = 0; a <= 56; ++a) {
      for (int b = 0; b <= 48; ++b)
        stock.stamp({8 + 0.25 * a, 9 + 0.25 * b});
    }
    stock.cut({22, 21}, {23.5, 23.2});
    const double ring = m->radius_mm + 0.5 * m->step_mm;
    const pocket::BitImage reach = pocket::cleared_reach(*m, stock, ring);
    auto in_reach = [&](int i, int j) {
      return reach.get(i >> pocket::kReachBlockShift, j >> pocket::kReachBlockShift);
    };
    const pocket::BitImage& mat = stock.material();
    std::size_t resumable = 0, wrong = 0;
    for (int j = 0; j < mat.height(); ++j) {
      for (int i = 0; i < mat.width(); ++i) {
        if (!mat.get(i, j)) continue;
        const Vec2 q = m->grid.to_world(i, j);
        bool any = false;
        for (int a = 0; a < 360 && !any; a += 15) {
          const Vec2 c = q + Vec2{std::cos(deg_to_rad(a)), std::sin(deg_to_rad(a))} * ring;
          any = !stock.gouges(c) && stock.material_in_disk(c, m->radius_mm + 0.5 * m->h, 0) == 0;
        }
        resumable += any ? 1 : 0;
        wrong += any && !in_reach(i, j) ? 1 : 0;
      }
    }
    EXPECT_GT(resumable, 1000U) << wall_stock;  // the test has resumes to find
    EXPECT_EQ(wrong, 0U) << wall_stock;
    for (const Vec2 far : {Vec2{75, 15}, Vec2{63, 3}, Vec2{87, 27}, Vec2{61, 29}}) {
      const Vec2 px = m->grid.to_px(far);
      EXPECT_FALSE(in_reach(static_cast<int>(px.x), static_cast<int>(px.y)))
          << far.x << ", " << far.y << " wall stock " << wall_stock;
    }
  }
}

}  // namespace
}  // namespace swarf
