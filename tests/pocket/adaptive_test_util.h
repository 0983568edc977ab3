// Helpers shared by the adaptive pocket's tests: test pockets, a flat end mill, parameters.
#pragma once

#include <gtest/gtest.h>

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

// A generated path as the machine would run it (its metrics) and as the independent sweep
// judges it, at 0.08 mm checker pixels with material within 0.25 mm of a wall taken for the
// resolution scallop (the tolerances of adaptive_test.cpp).
struct SweptPath {
  ToolpathMetrics metrics;
  SweepReport sweep;
};
inline SweptPath swept(const Pocket& p, double tool_d, const AdaptiveResult& r) {
  return {compute_metrics(r.toolpath),
          sweep_check(p.region, 0.5 * tool_d, r.toolpath, r.target_engagement_deg, 0.08, 0.25)};
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

}  // namespace swarf::testing
