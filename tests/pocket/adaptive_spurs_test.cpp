// Spurs (drop_spurs, src/pocket/wall_reach.cpp): a pass that ends against a wall, a step back
// along it that cuts nothing, and the next cut turning round past where the pass ended.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "pocket/adaptive_test_util.h"
#include "pocket/sweep_checker.h"
#include "swarf/pocket/adaptive.h"

namespace swarf {
namespace {

// Points a -> b -> c of the floor path where b -> c turns back by more than 150 degrees
// and goes out past a: the move a -> b was travelled for nothing.
int count_spurs(const Toolpath& tp, double floor_z) {
  std::vector<Vec2> pts;
  int spurs = 0;
  for (const Move& mv : tp.moves) {
    if (mv.kind == MoveKind::kRapid || std::abs(mv.end.z - floor_z) > 1e-6) {
      pts.clear();
      continue;
    }
    pts.push_back({mv.end.x, mv.end.y});
    if (pts.size() < 3) continue;
    const Vec2 a = pts[pts.size() - 3], b = pts[pts.size() - 2], c = pts.back();
    const Vec2 ab = b - a, bc = c - b;
    if (dot(ab, bc) < -0.866 * norm(ab) * norm(bc) && dot(c - a, a - b) > 0.0) ++spurs;
  }
  return spurs;
}

// A channel 2 mm wider than a ø10 at 1 mm stepover (as the two beside the L's square
// island): the crescents cross it, and each crossing used to end against the wall with a
// step back of a few tenths of a millimetre and the next crossing's first cut forward
// past it (39 spurs on this channel, each two reversals of the heading within half a
// millimetre). Leaving the steps back out must take the same material: nothing left
// beyond the allowance, no gouge, no slot.
TEST(AdaptiveSpurs, CrossingsOfAChannelTurnWithoutSteppingBack) {
  const Pocket p = make_pocket({{0, 0}, {40, 0}, {40, 12}, {0, 12}}, {}, "channel 12 x 40").value();
  AdaptiveParams params = testing::params_3mm_deep(1.0);
  auto r = adaptive_pocket(p, testing::flat_mill(10.0), params);
  ASSERT_TRUE(r.ok()) << r.status().to_string();
  const int spurs = count_spurs(r->toolpath, params.top_z_mm - params.depth_mm);
  const auto s = testing::sweep_check(p.region, 5.0, r->toolpath, r->target_engagement_deg,
                                      /*pixel_mm=*/0.05, /*residual_tol_mm=*/0.2);
  std::printf("  spurs %d, gouge %.4f mm, residual %.2f mm2, within20 %.1f %%, slot %.1f mm\n",
              spurs, s.max_gouge_mm, s.residual_mm2, 100 * s.within_20pct, s.slot_length_mm);
  EXPECT_LE(spurs, 8);
  EXPECT_LE(s.max_gouge_mm, 1e-6);
  EXPECT_LE(s.residual_mm2, 0.2);
  EXPECT_EQ(s.slot_length_mm, 0.0);
}

}  // namespace
}  // namespace swarf
