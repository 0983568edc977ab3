// The rounding of a cutting pass's turns between output moves (smooth_cutting_corners),
// judged by the independent sweep.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "pocket/adaptive_test_util.h"

namespace swarf {
namespace {

// The floor moves' end points, in order (the entry's helix left out).
std::vector<Vec3> floor_points(const Toolpath& tp, double floor_z) {
  std::vector<Vec3> pts;
  for (const Move& mv : tp.moves) {
    if (mv.kind == MoveKind::kFeed && std::abs(mv.end.z - floor_z) < 1e-9) pts.push_back(mv.end);
  }
  return pts;
}

// A slot 19 mm wide for a ø16 at 5 %: cleared by loops about 1.5 mm across, whose steps
// turn 10-20 degrees each (random pocket 1520 has channels like it round its islands).
// Rounded, the contact arc stops jumping by the turn at each move's end: the sweep's share
// of the cut within +-20 % rises by several points (at 0.04 mm, the bench's pixel for this
// tool: at 0.08 the arc of a 26-degree engagement reads too coarsely), with no gouge and
// nothing more left; every point of the unrounded path is still on the rounded one, in
// order, and few of its cutting moves still turn by much more than the rounding's bound
// (15 % of the target, at most 6 degrees).
TEST(AdaptiveCorners, TightTurnsAreRoundedThroughTheSamePointsAndHoldTheBandBetter) {
  const Pocket p = make_pocket({{0, 0}, {60, 0}, {60, 19}, {0, 19}}, {}, "slot 60 x 19").value();
  AdaptiveParams ap = testing::params_3mm_deep(0.8);
  ap.smooth_corners = false;
  const auto off = adaptive_pocket(p, testing::flat_mill(16.0), ap);
  ap.smooth_corners = true;
  const auto on = adaptive_pocket(p, testing::flat_mill(16.0), ap);
  ASSERT_TRUE(off.ok() && on.ok());
  const auto sweep = [&](const AdaptiveResult& r) {
    return testing::sweep_check(p.region, 8.0, r.toolpath, r.target_engagement_deg, 0.04, 0.25);
  };
  const testing::SweepReport s_off = sweep(*off), s_on = sweep(*on);
  std::printf("  within20 %.1f -> %.1f %%, residual %.2f -> %.2f mm2, moves %zu -> %zu\n",
              100 * s_off.within_20pct, 100 * s_on.within_20pct, s_off.residual_mm2,
              s_on.residual_mm2, off->toolpath.moves.size(), on->toolpath.moves.size());
  EXPECT_GE(s_on.within_20pct, s_off.within_20pct + 0.05);
  EXPECT_LE(s_on.max_gouge_mm, 1e-6);
  EXPECT_LE(s_on.residual_mm2, s_off.residual_mm2 + 0.05);

  const double floor_z = ap.top_z_mm - ap.depth_mm;
  const std::vector<Vec3> a = floor_points(off->toolpath, floor_z);
  const std::vector<Vec3> b = floor_points(on->toolpath, floor_z);
  std::size_t k = 0;
  for (const Vec3& q : b) {
    if (k < a.size() && norm(q - a[k]) < 1e-12) ++k;
  }
  EXPECT_EQ(k, a.size()) << "a point of the unrounded path is not on the rounded one";

  // Turns between consecutive cutting floor moves, over twice the bound and up to 60
  // degrees: nine in ten before, under one in ten after (the moves on the walls' offset,
  // those next to a corner and those whose pieces would come within a pixel of the
  // offset stay straight, and a move takes 8 pieces at most).
  const double bound = std::clamp(0.15 * on->target_engagement_deg, 2.0, 6.0);
  auto sharp_turns = [&](const Toolpath& tp) {
    std::size_t n = 0, all = 0;
    for (std::size_t i = 2; i < tp.moves.size(); ++i) {
      const Move &m0 = tp.moves[i - 2], &m1 = tp.moves[i - 1], &m2 = tp.moves[i];
      const bool floor = m0.end.z == floor_z && m1.end.z == floor_z && m2.end.z == floor_z;
      if (!floor || m1.kind != MoveKind::kFeed || m2.kind != MoveKind::kFeed || !m1.cutting ||
          !m2.cutting)
        continue;
      const Vec2 u = m1.end.xy() - m0.end.xy(), v = m2.end.xy() - m1.end.xy();
      if (norm(u) < 1e-9 || norm(v) < 1e-9) continue;
      const double t =
          rad_to_deg(std::acos(std::clamp(dot(u, v) / (norm(u) * norm(v)), -1.0, 1.0)));
      ++all;
      n += t > 2.0 * bound && t <= 60.0 ? 1 : 0;
    }
    return static_cast<double>(n) / static_cast<double>(std::max<std::size_t>(all, 1));
  };
  const double before = sharp_turns(off->toolpath), after = sharp_turns(on->toolpath);
  std::printf("  turns over %.1f deg: %.1f -> %.1f %% of the cutting moves\n", 2 * bound,
              100 * before, 100 * after);
  EXPECT_GT(before, 0.5);
  EXPECT_LT(after, 0.1);
}

}  // namespace
}  // namespace swarf
