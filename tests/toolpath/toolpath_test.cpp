// Toolpath builders, exact move lengths, sampling and metrics on hand-computed paths.
#include <gtest/gtest.h>

#include <cmath>

#include "swarf/toolpath/metrics.h"
#include "swarf/toolpath/toolpath.h"

namespace swarf {
namespace {

TEST(ToolpathBuilders, PositionStartsAtClearanceAndFollowsMoves) {
  Toolpath p;
  p.clearance_z_mm = 7.5;
  EXPECT_EQ(p.position(), (Vec3{0.0, 0.0, 7.5}));
  p.rapid_to({1.0, 2.0, 7.5});
  p.plunge_to(-3.0, 200.0);
  ASSERT_EQ(p.moves.size(), 2u);
  EXPECT_EQ(p.moves[0].kind, MoveKind::kRapid);
  EXPECT_FALSE(p.moves[0].cutting);
  EXPECT_EQ(p.moves[1].kind, MoveKind::kPlunge);
  EXPECT_EQ(p.moves[1].end, (Vec3{1.0, 2.0, -3.0}));  // straight down, xy kept
  EXPECT_EQ(p.moves[1].feed_mm_min, 200.0);
  p.ramp_to({4.0, 2.0, -4.0}, 300.0);
  EXPECT_EQ(p.moves.back().kind, MoveKind::kRamp);
  p.feed_to({5.0, 2.0, -4.0}, 400.0, false);
  EXPECT_FALSE(p.moves.back().cutting);
  p.arc_to({5.0, 2.0, -4.0}, {6.0, 2.0}, true, 500.0);
  EXPECT_EQ(p.moves.back().kind, MoveKind::kArc);
  EXPECT_EQ(p.moves.back().center, (Vec3{6.0, 2.0, -4.0}));
  EXPECT_TRUE(p.moves.back().clockwise);
  p.arc_to({7.0, 2.0, -5.0}, {6.0, 2.0}, false, 500.0);
  EXPECT_EQ(p.moves.back().kind, MoveKind::kHelix);
  p.retract();
  EXPECT_EQ(p.moves.back().kind, MoveKind::kRapid);
  EXPECT_EQ(p.moves.back().end, (Vec3{7.0, 2.0, 7.5}));
  EXPECT_EQ(p.position(), (Vec3{7.0, 2.0, 7.5}));
}

TEST(ToolpathLength, LinesAndArcsAgainstClosedForms) {
  Move line;
  line.end = {3.0, 4.0, 12.0};
  EXPECT_DOUBLE_EQ(move_length({0, 0, 0}, line), 13.0);

  Move arc;
  arc.kind = MoveKind::kArc;
  arc.center = {0, 0, 0};
  arc.end = {0.0, -5.0, 0.0};
  arc.clockwise = true;  // (5,0) -> (0,-5) clockwise: a quarter turn
  EXPECT_NEAR(move_length({5, 0, 0}, arc), 5.0 * kPi / 2.0, 1e-12);
  arc.clockwise = false;  // the other way round: three quarters
  EXPECT_NEAR(move_length({5, 0, 0}, arc), 15.0 * kPi / 2.0, 1e-12);
  arc.end = {5.0, 0.0, 0.0};  // start == end: a full circle, as G2/G3 define it
  EXPECT_NEAR(move_length({5, 0, 0}, arc), 10.0 * kPi, 1e-12);
}

TEST(ToolpathLength, HelixIsUnrolledCircle) {
  Move h;
  h.kind = MoveKind::kHelix;
  h.center = {1.0, 1.0, 0.0};
  h.end = {-4.0, 1.0, -1.0};  // half a turn of radius 5, 1 mm down
  EXPECT_NEAR(move_length({6.0, 1.0, 0.0}, h), std::sqrt(25.0 * kPi * kPi + 1.0), 1e-12);
  h.end = {6.0, 1.0, -2.0};  // a full turn, 2 mm down
  EXPECT_NEAR(move_length({6.0, 1.0, 0.0}, h), std::sqrt(100.0 * kPi * kPi + 4.0), 1e-12);
}

TEST(ToolpathLength, ZxPlaneArcDirectionSeenFromPlusY) {
  // G18: clockwise seen from +Y. From (x=5, z=0) to (x=0, z=5) about the origin: seen from
  // +Y (x to the left, z up, looking toward -Y) that is a quarter turn clockwise.
  Move a;
  a.kind = MoveKind::kArc;
  a.plane = ArcPlane::kZX;
  a.center = {0, 0, 0};
  a.end = {0.0, 0.0, 5.0};
  a.clockwise = true;
  EXPECT_NEAR(move_length({5, 0, 0}, a), 5.0 * kPi / 2.0, 1e-12);
  a.clockwise = false;
  EXPECT_NEAR(move_length({5, 0, 0}, a), 15.0 * kPi / 2.0, 1e-12);
}

TEST(ToolpathSample, HelixPointsLieOnTheHelix) {
  Move h;
  h.kind = MoveKind::kHelix;
  h.center = {0, 0, 0};
  h.end = {0.0, 5.0, -3.0};
  h.clockwise = false;  // (5,0,0) -> (0,5,-3): a quarter turn ccw
  const auto pts = sample_move({5, 0, 0}, h, 0.1);
  const double len = move_length({5, 0, 0}, h);
  ASSERT_GE(pts.size(), static_cast<std::size_t>(std::ceil(len / 0.1)));
  EXPECT_EQ(pts.back(), h.end);
  Vec3 prev{5, 0, 0};
  for (const Vec3& p : pts) {
    EXPECT_NEAR(norm(p.xy()), 5.0, 1e-9);
    EXPECT_LE(distance(prev, p), 0.1 + 1e-12);
    const double angle = std::atan2(p.y, p.x);  // 0 .. pi/2
    EXPECT_GE(angle, -1e-12);
    EXPECT_NEAR(p.z, -3.0 * angle / (kPi / 2.0), 1e-9);  // z linear in angle
    prev = p;
  }
  Move line;
  line.end = {1, 2, 3};
  EXPECT_EQ(sample_move({0, 0, 0}, line, 0.01).size(), 1u);
}

TEST(ToolpathMetrics, SquareAtKnownFeedTakesKnownTime) {
  Toolpath p;
  p.clearance_z_mm = 5.0;
  p.rapid_to({0, 0, 5});     // from the unknown machine position: not counted
  p.plunge_to(-1.0, 300.0);  // 6 mm at 300 mm/min = 1.2 s
  p.feed_to({10, 0, -1}, 600.0);
  p.feed_to({10, 10, -1}, 600.0);
  p.feed_to({0, 10, -1}, 600.0);
  p.feed_to({0, 0, -1}, 600.0);  // 40 mm at 600 mm/min = 4 s
  p.retract();                   // 6 mm rapid at 5000 mm/min = 0.072 s
  const ToolpathMetrics m = compute_metrics(p);
  EXPECT_EQ(m.moves, 7u);
  EXPECT_NEAR(m.cutting_length_mm, 46.0, 1e-12);
  EXPECT_NEAR(m.rapid_length_mm, 6.0, 1e-12);
  EXPECT_NEAR(m.air_length_mm, 6.0, 1e-12);
  EXPECT_EQ(m.lift_offs, 0u);  // the final retract is not a lift-off
  EXPECT_NEAR(m.machining_time_s, 1.2 + 4.0 + 0.072, 1e-12);
  MetricsOptions slow;
  slow.rapid_mm_min = 600.0;
  EXPECT_NEAR(compute_metrics(p, slow).machining_time_s, 1.2 + 4.0 + 0.6, 1e-12);
}

TEST(ToolpathMetrics, LiftOffsBetweenCutsAndAirFeeds) {
  Toolpath p;
  p.clearance_z_mm = 3.0;
  p.rapid_to({0, 0, 3});
  for (int i = 0; i < 3; ++i) {
    const double x = 10.0 * i;
    p.rapid_to({x, 0, 3});
    p.plunge_to(-1.0, 100.0);
    p.feed_to({x + 5, 0, -1}, 500.0);
    p.feed_to({x + 5, 2, -1}, 500.0, false);  // a link in air: 2 mm
    p.retract();
  }
  const ToolpathMetrics m = compute_metrics(p);
  EXPECT_EQ(m.lift_offs, 2u);  // three cuts, two lifts between them
  EXPECT_NEAR(m.cutting_length_mm, 3 * (4.0 + 5.0), 1e-12);
  // Rapids: three 4 mm retracts and two traverses (x+5, 2) -> (x+10, 0) at clearance.
  const double rapids = 3 * 4.0 + 2 * std::hypot(5.0, 2.0);
  EXPECT_NEAR(m.rapid_length_mm, rapids, 1e-12);
  EXPECT_NEAR(m.air_length_mm, rapids + 3 * 2.0, 1e-12);
  const double time = 3 * (4.0 / 100.0 + 5.0 / 500.0 + 2.0 / 500.0) * 60.0 + rapids / 5000.0 * 60.0;
  EXPECT_NEAR(m.machining_time_s, time, 1e-12);
}

TEST(ToolpathMetrics, ArcTimeUsesExactLength) {
  Toolpath p;
  p.rapid_to({5, 0, 0});
  p.arc_to({5, 0, -2}, {0, 0}, false, 100.0);
  const double len = std::sqrt(100.0 * kPi * kPi + 4.0);
  const ToolpathMetrics m = compute_metrics(p);
  EXPECT_NEAR(m.cutting_length_mm, len, 1e-12);
  EXPECT_NEAR(m.machining_time_s, len / 100.0 * 60.0, 1e-12);
  EXPECT_EQ(compute_metrics(Toolpath{}).moves, 0u);
}

}  // namespace
}  // namespace swarf
