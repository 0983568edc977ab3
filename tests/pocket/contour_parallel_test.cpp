#include <gtest/gtest.h>

#include <cstdio>

#include "pocket/sweep_checker.h"
#include "swarf/pocket/contour_parallel.h"

namespace swarf {
namespace {

TEST(ContourParallel, LWithIslandsHasNoGougeAndLeavesOnlyUnreachableMaterial) {
  auto p = make_pocket(
      {{0, 0}, {60, 0}, {60, 24}, {30, 24}, {30, 48}, {0, 48}},
      {{{42, 7}, {48, 7}, {48, 17}, {42, 17}}, {{12, 30}, {18, 30}, {18, 36}, {12, 36}}},
      "L 60x48");
  ASSERT_TRUE(p.ok());
  Tool t;
  t.diameter_mm = 6.0;
  ContourParallelParams cp;
  cp.stepover_mm = 0.6;
  cp.depth_mm = 3.0;
  auto r = contour_parallel_pocket(*p, t, cp);
  ASSERT_TRUE(r.ok()) << r.status().to_string();
  const auto s = testing::sweep_check(p->region, 3.0, r->toolpath, 36.87, 0.08, 0.25);
  std::printf(
      "  contour L: gouge %.3f mm, residual %.2f mm2, rings %d, retracts %d, max eng %.0f\n",
      s.max_gouge_mm, s.residual_mm2, r->rings, r->retracts_per_layer, s.max_engagement_deg);
  // By exact geometry: the round joins round the islands' corners are chords that cut in by
  // up to the arc tolerance, so the rings next to the walls go round them 2 um off instead;
  // what is left is Clipper's 1e-5 mm grid at the offset's own vertices.
  EXPECT_LE(s.max_gouge_mm, 1e-5);
  EXPECT_LE(s.residual_mm2, 0.5);
}

TEST(ContourParallel, WholeDepthBeyondTheFlutesIsABadParameter) {
  auto p = make_pocket({{0, 0}, {40, 0}, {40, 40}, {0, 40}}, {}, "square");
  ASSERT_TRUE(p.ok());
  Tool t;
  t.diameter_mm = 6.0;
  t.flute_length_mm = 10.0;
  ContourParallelParams cp;
  cp.depth_mm = 12.0;  // stepdown 0: one 12 mm layer, deeper than the 10 mm flutes
  auto r = contour_parallel_pocket(*p, t, cp);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), Error::kBadParameter);
  EXPECT_NE(r.status().to_string().find("flute"), std::string::npos) << r.status().to_string();
  cp.stepdown_mm = 11.0;  // a layer deeper than the flutes
  EXPECT_EQ(contour_parallel_pocket(*p, t, cp).status().code(), Error::kBadParameter);
  cp.stepdown_mm = 6.0;  // two 6 mm layers fit
  EXPECT_TRUE(contour_parallel_pocket(*p, t, cp).ok());
}

TEST(ContourParallel, ToolTooLarge) {
  auto p = make_pocket({{0, 0}, {5, 0}, {5, 5}, {0, 5}}, {}, "small");
  Tool t;
  t.diameter_mm = 6.0;
  auto r = contour_parallel_pocket(*p, t, ContourParallelParams{});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), Error::kToolTooLarge);
}

}  // namespace
}  // namespace swarf
