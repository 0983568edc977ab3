// Correctness of the adaptive pocket (issue item 6), judged by the independent sweep of
// tests/pocket/sweep_checker.cpp on the final toolpath.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "pocket/sweep_checker.h"
#include "swarf/pocket/adaptive.h"

namespace swarf {
namespace {

Pocket load(const std::string& name) {
  auto p = read_pocket(std::string(SWARF_TEST_DATA_DIR) + "/pocket/" + name);
  EXPECT_TRUE(p.ok()) << p.status().to_string();
  return p.value();
}

Pocket scaled(const Pocket& p, double s) {
  Ring outer;
  for (Vec2 q : p.outer())
    outer.push_back(q * s);
  std::vector<Ring> islands;
  for (std::size_t k = 1; k < p.region.rings.size(); ++k) {
    islands.push_back({});
    for (Vec2 q : p.region.rings[k])
      islands.back().push_back(q * s);
  }
  return make_pocket(outer, islands, p.source).value();
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

struct Outcome {
  AdaptiveResult result;
  testing::SweepReport sweep;
};

Outcome run(const Pocket& p, double tool_d, double stepover_mm) {
  Tool t;  // a flat end mill (Tool's defaults), built here so the test needs no tool parser
  t.diameter_mm = tool_d;
  AdaptiveParams ap;
  ap.stepover_mm = stepover_mm;
  ap.depth_mm = 3.0;
  auto r = adaptive_pocket(p, t, ap);
  EXPECT_TRUE(r.ok()) << r.status().to_string();
  Outcome o{r.value(), {}};
  o.sweep = testing::sweep_check(p.region, 0.5 * tool_d, o.result.toolpath,
                                 o.result.target_engagement_deg, 0.05, 0.2);
  const auto& s = o.sweep;
  std::printf(
      "  %s: gouge %.3f mm, residual %.2f mm2 (unreachable %.1f), cutting %.0f mm, "
      "within20 %.1f %%, max eng %.0f deg, slot %.1f mm, pixel %.3f mm\n",
      p.source.c_str(), s.max_gouge_mm, s.residual_mm2, s.unreachable_mm2, s.cutting_length_mm,
      100 * s.within_20pct, s.max_engagement_deg, s.slot_length_mm, o.result.resolution_mm);
  return o;
}

// Tolerances stated once: the tool may pass a wall by at most the generator's pixel plus the
// checker's; material thinner than kWallTol against a wall is the resolution scallop, not
// residual; residual beyond that at most kResidualMm2 (a few checker pixels per corner).
constexpr double kCheckerPixel = 0.05;
constexpr double kResidualMm2 = 0.5;

void expect_correct(const Outcome& o, bool check_engagement) {
  const auto& s = o.sweep;
  EXPECT_LE(s.max_gouge_mm, o.result.resolution_mm + kCheckerPixel);
  EXPECT_LE(s.residual_mm2, kResidualMm2);
  if (check_engagement) {
    EXPECT_GE(s.within_20pct, 0.95);
    EXPECT_EQ(s.slot_length_mm, 0.0);
  }
}

TEST(AdaptivePocket, LPocket) {
  const Pocket l = scaled(load("l_pocket_islands.json"), 0.6);
  Pocket plain = make_pocket(l.outer(), {}, "L 60x48").value();
  expect_correct(run(plain, 6.0, 0.6), true);
}

TEST(AdaptivePocket, LPocketWithRoundAndRectangularIsland) {
  Pocket l = scaled(load("l_pocket_islands.json"), 0.6);
  l.source = "L 60x48 with islands";
  expect_correct(run(l, 6.0, 0.6), true);
}

TEST(AdaptivePocket, ChannelBarelyWiderThanTheTool) {
  Pocket ch = make_pocket({{0, 0}, {40, 0}, {40, 6.6}, {0, 6.6}}, {}, "channel 6.6 x 40").value();
  const Outcome o = run(ch, 6.0, 0.6);
  expect_correct(o, false);
  // No helix fits: the entry is a ramp along the channel.
  EXPECT_EQ(o.result.helix_radius_mm, 0.0);
}

TEST(AdaptivePocket, StarWithSharpCorners) {
  expect_correct(run(star(30.0, 14.0, 5), 6.0, 0.6), true);
}

TEST(AdaptivePocket, KirimotoPocketFromARealPart) {
  expect_correct(run(load("kirimoto_pocket.json"), 10.0, 1.0), true);
}

TEST(AdaptivePocket, PcbViceBarSliceFromARealPart) {
  expect_correct(run(load("pcbvicebar_slice.json"), 6.0, 0.6), true);
}

TEST(AdaptivePocket, ToolTooLargeAndNoEntryAreNamedErrors) {
  Pocket narrow = make_pocket({{0, 0}, {40, 0}, {40, 5}, {0, 5}}, {}, "narrow").value();
  Tool t;
  t.diameter_mm = 6.0;
  auto r = adaptive_pocket(narrow, t, AdaptiveParams{});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), Error::kToolTooLarge);
  // A square just wider than the tool: it fits, but there is no room to helix or ramp.
  Pocket tight = make_pocket({{0, 0}, {6.1, 0}, {6.1, 6.1}, {0, 6.1}}, {}, "tight").value();
  auto q = adaptive_pocket(tight, t, AdaptiveParams{});
  ASSERT_FALSE(q.ok());
  EXPECT_EQ(q.status().code(), Error::kNoEntryFound) << q.status().to_string();
}

TEST(AdaptivePocket, StepoverAndEngagementAngleAreTheSameParameter) {
  // acos(1 - stepover / R): 10 % of a 10 mm tool is 36.87 degrees.
  EXPECT_NEAR(engagement_angle_deg(1.0, 5.0), rad_to_deg(std::acos(0.8)), 1e-12);
  EXPECT_NEAR(stepover_for_angle_mm(engagement_angle_deg(1.3, 5.0), 5.0), 1.3, 1e-12);
}

}  // namespace
}  // namespace swarf
