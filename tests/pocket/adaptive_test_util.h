// Helpers shared by the adaptive pocket's tests: test pockets, a flat end mill, parameters.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "pocket/sweep_checker.h"
#include "swarf/pocket/adaptive.h"
#include "swarf/toolpath/metrics.h"

namespace swarf::testing {

// A pocket of tests/data/pocket.
inline Pocket load_test_pocket(const std::string& name) {
  auto p = read_pocket(std::string(SWARF_TEST_DATA_DIR) + "/pocket/" + name);
  EXPECT_TRUE(p.ok()) << p.status().to_string();
  return p.value();
}

// The pocket scaled by s about the origin.
inline Pocket scaled(const Pocket& p, double s) {
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

// Two 30 x 30 mm chambers joined by a channel 15 mm long and 10.1 mm wide, for a ø10 (a
// tenth wider, as the necks of random pockets 1088 and 1096; from 0.3 wider the path gets
// through without a slot).
inline Pocket dumbbell_pocket() {
  return make_pocket({{0, 0},
                      {30, 0},
                      {30, 10},
                      {45, 10},
                      {45, 0},
                      {75, 0},
                      {75, 30},
                      {45, 30},
                      {45, 20.1},
                      {30, 20.1},
                      {30, 30},
                      {0, 30}},
                     {}, "dumbbell")
      .value();
}

// A flat end mill (Tool's defaults), built here so the tests need no tool parser.
inline Tool flat_mill(double diameter_mm) {
  Tool t;
  t.diameter_mm = diameter_mm;
  return t;
}

// A stepover and a 3 mm deep pocket, the rest defaults.
inline AdaptiveParams params_3mm_deep(double stepover_mm) {
  AdaptiveParams ap;
  ap.stepover_mm = stepover_mm;
  ap.depth_mm = 3.0;
  return ap;
}

// The sweep's tolerances, stated once: the tool may pass a wall by at most the generator's pixel
// plus the checker's; material within kWallTol of a wall is the resolution scallop (the generator
// keeps half a pixel off the wall and boundary steps turn in whole degrees), not residual.
constexpr double kCheckerPixel = 0.08;
constexpr double kWallTol = 0.25;
// Residual beyond that: at most kResidualPerCornerMm2 per corner of the pocket where the
// walls meet at less than 180 degrees inside. The path visits the exact tips of the tool
// centres' region (adaptive.cpp, reach_into_tips), so what is left there is a few checker
// pixels; before that it was 1.5 to 6 mm^2 per pocket and this allowance 1.2 per corner.
constexpr double kResidualPerCornerMm2 = 0.1;

// A generated path as the machine would run it (its metrics) and as the independent sweep
// judges it, at the tolerances above.
struct SweptPath {
  ToolpathMetrics metrics;
  SweepReport sweep;
};
inline SweptPath swept(const Pocket& p, double tool_d, const AdaptiveResult& r) {
  return {compute_metrics(r.toolpath),
          sweep_check(p.region, 0.5 * tool_d, r.toolpath, r.target_engagement_deg, kCheckerPixel,
                      kWallTol)};
}

// The pocket generated with `ap` for a ø tool_d flat end mill, and swept; prints the sweep's
// milling side, smoothness and band figures under `label`.
inline SweptPath generate_swept(const Pocket& p, double tool_d, const AdaptiveParams& ap,
                                const std::string& label) {
  auto r = adaptive_pocket(p, flat_mill(tool_d), ap);
  EXPECT_TRUE(r.ok()) << r.status().to_string();
  if (!r.ok()) return {};
  const SweptPath out = swept(p, tool_d, *r);
  const auto& s = out.sweep;
  std::printf(
      "  %s, %s: climb %.1f %%, reversals %.1f per m, within20 %.2f %%, residual %.2f mm2, "
      "slot %.1f mm, machining %.0f s\n",
      p.source.c_str(), label.c_str(), 100 * s.climb_share,
      1000.0 * s.reversals / s.floor_length_mm, 100 * s.within_20pct, s.residual_mm2,
      s.slot_length_mm, out.metrics.machining_time_s);
  return out;
}

// How the passes run: the milling side, one way or both, straight or smooth links.
struct PassRule {
  bool climb = true;
  bool one_way = false;
  bool smooth_links = false;
};

// The pocket generated with params_3mm_deep(stepover_mm) and `rule`, and swept; the label
// printed says the rule.
inline SweptPath generate_swept(const Pocket& p, double tool_d, double stepover_mm, PassRule rule) {
  AdaptiveParams ap = params_3mm_deep(stepover_mm);
  ap.climb = rule.climb;
  ap.one_way = rule.one_way;
  ap.smooth_links = rule.smooth_links;
  return generate_swept(p, tool_d, ap,
                        std::string(rule.climb ? "climb" : "conventional") +
                            (rule.one_way ? ", one way" : ", both ways") +
                            (rule.smooth_links ? ", smooth links" : ", straight links"));
}

// The correctness checks of adaptive_test.cpp and adaptive_random_test.cpp (issue item 6).

inline int convex_corners(const Pocket& p) {
  int n = 0;
  const Ring& r = p.outer();  // counter-clockwise: a left turn is a corner < 180 degrees
  for (std::size_t k = 0; k < r.size(); ++k) {
    const Vec2 a = r[(k + r.size() - 1) % r.size()], b = r[k], c = r[(k + 1) % r.size()];
    if (cross(b - a, c - b) > 1e-9 &&
        std::abs(std::atan2(cross(b - a, c - b), dot(b - a, c - b))) > 0.2)
      ++n;
  }
  return n;
}

// A generated path and what the sweep reads of it.
struct Outcome {
  AdaptiveResult result;
  SweepReport sweep;
};

inline Result<AdaptiveResult> generate(const Pocket& p, double tool_d, double stepover_mm) {
  return adaptive_pocket(p, flat_mill(tool_d), params_3mm_deep(stepover_mm));
}

inline Outcome run(const Pocket& p, double tool_d, double stepover_mm) {
  auto r = generate(p, tool_d, stepover_mm);
  EXPECT_TRUE(r.ok()) << r.status().to_string();
  Outcome o{r.value(), {}};
  o.sweep = sweep_check(p.region, 0.5 * tool_d, o.result.toolpath, o.result.target_engagement_deg,
                        kCheckerPixel, kWallTol);
  const auto& s = o.sweep;
  std::printf(
      "  %s: gouge %.3f mm, residual %.2f mm2 (unreachable %.1f), cutting %.0f mm, "
      "within20 %.1f %% (by removal %.1f %%), max eng %.0f deg, slot %.1f mm, pixel %.3f mm\n",
      p.source.c_str(), s.max_gouge_mm, s.residual_mm2, s.unreachable_mm2, s.cutting_length_mm,
      100 * s.within_20pct, 100 * s.within_20pct_removal, s.max_engagement_deg, s.slot_length_mm,
      o.result.resolution_mm);
  return o;
}

// A pocket of tests/data/pocket generated and swept at the given checker pixel and wall
// tolerance (coarse for large tools on long paths, where 0.08 mm takes tens of seconds).
inline SweepReport sweep_of(const std::string& file, double tool_d, double stepover_mm,
                            double pixel_mm, double wall_tol_mm) {
  const Pocket p = load_test_pocket(file);
  auto r = generate(p, tool_d, stepover_mm);
  EXPECT_TRUE(r.ok()) << r.status().to_string();
  if (!r.ok()) return {};
  const auto s = sweep_check(p.region, 0.5 * tool_d, r->toolpath, r->target_engagement_deg,
                             pixel_mm, wall_tol_mm);
  std::printf("  %s: residual %.2f mm2, within20 %.1f %%\n", file.c_str(), s.residual_mm2,
              100 * s.within_20pct);
  return s;
}

// within20: the issue asks for +-20 % of the target over 95 % of the cutting length; the
// tests assert what the method reaches today (a regression fails) and docs/pocket.md states
// the gap. A negative value skips the engagement checks (the channel is all slot).
// within20_removal: the same by the removal measure of the checker.
inline void expect_correct(const Pocket& p, const Outcome& o, double within20,
                           double within20_removal = -1.0) {
  const auto& s = o.sweep;
  // By exact geometry (the checker's point-to-edge distances along the whole path): passes
  // along walls keep 2 um off them, and neither the output simplification nor a straight move
  // round an island's corner may cut in (they did by up to 23 um).
  EXPECT_LE(s.max_gouge_mm, 1e-6);
  EXPECT_LE(s.residual_mm2, kResidualPerCornerMm2 * std::max(1, convex_corners(p)));
  if (within20 >= 0.0) {
    EXPECT_GE(s.within_20pct, within20);
    EXPECT_GE(s.within_20pct_removal, within20_removal);
    EXPECT_EQ(s.slot_length_mm, 0.0);
  }
}

// A pocket of tests/data/pocket (one of bench/pocket_random.sh's) generated, swept and held
// to no gouge and the residual allowance; the engagement is left to the caller.
inline Outcome expect_random_pocket_correct(const std::string& file, double tool_d,
                                            double stepover_mm) {
  const Pocket p = load_test_pocket(file);
  Outcome o = run(p, tool_d, stepover_mm);
  expect_correct(p, o, -1.0);
  return o;
}

}  // namespace swarf::testing
