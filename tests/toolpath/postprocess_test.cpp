// Post-processing against brute-force checks and analytic shapes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "swarf/toolpath/postprocess.h"

namespace swarf {
namespace {

template <class V>
double dist_to_segment(V p, V a, V b) {
  const V ab = b - a;
  const double l2 = norm_sq(ab);
  if (l2 == 0.0) return distance(p, a);
  const double t = std::clamp(dot(p - a, ab) / l2, 0.0, 1.0);
  return distance(p, a + ab * t);
}

/// Every dropped point lies within tol of the simplified segment that replaced it, and the
/// output is a subsequence of the input keeping both ends.
template <class V>
void expect_dp_within(const std::vector<V>& in, const std::vector<V>& out, double tol) {
  ASSERT_GE(out.size(), std::min<std::size_t>(in.size(), 2));
  EXPECT_EQ(out.front(), in.front());
  EXPECT_EQ(out.back(), in.back());
  std::size_t k = 0;  // index into `in` of out[j]
  for (std::size_t j = 0; j + 1 < out.size(); ++j) {
    while (k < in.size() && !(in[k] == out[j]))
      ++k;
    ASSERT_LT(k, in.size()) << "output point " << j << " is not an input point in order";
    std::size_t next = k + 1;
    while (next < in.size() && !(in[next] == out[j + 1]))
      ++next;
    ASSERT_LT(next, in.size());
    for (std::size_t d = k + 1; d < next; ++d) {
      ASSERT_LE(dist_to_segment(in[d], out[j], out[j + 1]), tol) << "dropped point " << d;
    }
    k = next;
  }
}

TEST(PostprocessDouglasPeucker, NeverMovesAPointMoreThanTheTolerance2D) {
  std::mt19937 rng(12345);
  std::normal_distribution<double> step(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Vec2> pts{{0, 0}};
    const int n = 2 + trial * 25;
    for (int i = 1; i < n; ++i) {
      // A drifting random walk: long near-straight stretches and sharp turns.
      pts.push_back(pts.back() + Vec2{1.0 + 0.3 * step(rng), 0.4 * step(rng)});
      if (i % 37 == 0) pts.push_back(pts.back() - Vec2{5.0, 0.0});  // doubling back
    }
    for (double tol : {0.01, 0.1, 0.5, 2.0}) {
      const auto out = simplify_polyline(pts, tol);
      expect_dp_within(pts, out, tol);
    }
  }
}

TEST(PostprocessDouglasPeucker, NeverMovesAPointMoreThanTheTolerance3D) {
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> pts;
  for (int i = 0; i < 2000; ++i) {
    const double t = 0.01 * i;
    pts.push_back({10 * std::cos(t) + 0.05 * u(rng), 10 * std::sin(t), -0.1 * t + 0.05 * u(rng)});
  }
  for (double tol : {0.02, 0.1, 1.0}) {
    const auto out = simplify_polyline(pts, tol);
    EXPECT_LT(out.size(), pts.size());
    expect_dp_within(pts, out, tol);
  }
  // Collinear points collapse to the two ends.
  std::vector<Vec3> line;
  for (int i = 0; i <= 100; ++i)
    line.push_back({0.5 * i, 0.25 * i, -0.1 * i});
  EXPECT_EQ(simplify_polyline(line, 1e-9).size(), 2u);
}

TEST(PostprocessDouglasPeucker, MillionPointsWithoutRecursion) {
  // A curve whose farthest point is always next to the segment's end drives a recursive
  // Douglas-Peucker a million frames deep.
  std::vector<Vec2> pts;
  const int n = 1000000;
  pts.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double x = static_cast<double>(i) / n;
    pts.push_back({x, std::pow(x, 64.0)});
  }
  const auto out = simplify_polyline(pts, 1e-7);
  EXPECT_GT(out.size(), 2u);
  EXPECT_EQ(out.front(), pts.front());
  EXPECT_EQ(out.back(), pts.back());
}

TEST(PostprocessChaikin, RightAngleStaysInHullAndKeepsEnds) {
  const std::vector<Vec2> corner{{0, 0}, {10, 0}, {10, 10}};
  const auto once = chaikin_smooth(corner, 1);
  ASSERT_EQ(once.size(), 4u);
  EXPECT_EQ(once[1], (Vec2{7.5, 0.0}));   // 1 - ratio along the first edge
  EXPECT_EQ(once[2], (Vec2{10.0, 2.5}));  // ratio along the second
  std::size_t expected = 3;
  for (int it = 1; it <= 5; ++it) {
    const auto out = chaikin_smooth(corner, it);
    expected = 2 * (expected - 1);
    EXPECT_EQ(out.size(), expected);
    EXPECT_EQ(out.front(), corner.front());
    EXPECT_EQ(out.back(), corner.back());
    for (const Vec2& p : out) {
      // Inside the triangle (0,0) (10,0) (10,10): y >= 0, x <= 10, y <= x.
      EXPECT_GE(p.y, -1e-12);
      EXPECT_LE(p.x, 10.0 + 1e-12);
      EXPECT_LE(p.y, p.x + 1e-12);
      EXPECT_FALSE(p == corner[1]);  // the corner itself is cut away
    }
  }
  EXPECT_EQ(chaikin_smooth(corner, 0), corner);
  const std::vector<Vec2> two{{0, 0}, {1, 1}};
  EXPECT_EQ(chaikin_smooth(two, 3), two);
}

Toolpath polygon_circle(int segments, double r, bool clockwise, double z = -1.0) {
  Toolpath p;
  p.rapid_to({r, 0, z});
  for (int i = 1; i <= segments; ++i) {
    const double a = (clockwise ? -1.0 : 1.0) * 2.0 * kPi * i / segments;
    p.feed_to({r * std::cos(a), r * std::sin(a), z}, 800.0);
  }
  return p;
}

TEST(PostprocessFitArcs, PolygonisedCircleBecomesFewArcsOnTheCircle) {
  for (bool cw : {false, true}) {
    const Toolpath poly = polygon_circle(360, 20.0, cw);
    ArcFitOptions opt;
    const Toolpath fitted = fit_arcs(poly, opt);
    std::size_t arcs = 0;
    for (const Move& m : fitted.moves)
      arcs += m.kind == MoveKind::kArc;
    EXPECT_GE(arcs, 1u);
    EXPECT_LE(arcs, 3u);
    EXPECT_LE(fitted.moves.size(), 6u);
    EXPECT_EQ(fitted.moves.back().end, poly.moves.back().end);
    Vec3 pos = fitted.moves.front().end;
    for (std::size_t i = 1; i < fitted.moves.size(); ++i) {
      const Move& m = fitted.moves[i];
      if (m.is_arc()) {
        EXPECT_EQ(m.clockwise, cw);
        EXPECT_EQ(m.feed_mm_min, 800.0);
        for (const Vec3& s : sample_move(pos, m, 0.05)) {
          EXPECT_NEAR(norm(s.xy()), 20.0, opt.tolerance_mm);
          EXPECT_EQ(s.z, -1.0);
        }
      }
      pos = m.end;
    }
  }
}

TEST(PostprocessFitArcs, NoisyPointsStayWithinToleranceOfTheirArc) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> noise(-0.002, 0.002);
  Toolpath poly;
  poly.rapid_to({0, 0, 0});
  poly.feed_to({10, 0, 0}, 500.0);
  for (int i = 1; i <= 90; ++i) {  // a quarter circle of radius 10 about (10, 10) plus noise
    const double a = -kPi / 2 + kPi / 2 * i / 90.0;
    const double r = 10.0 + noise(rng);
    poly.feed_to({10 + r * std::cos(a), 10 + r * std::sin(a), 0}, 500.0);
  }
  poly.feed_to({20, 30, 0}, 500.0);
  ArcFitOptions opt;
  const Toolpath fitted = fit_arcs(poly, opt);
  EXPECT_LT(fitted.moves.size(), poly.moves.size() / 4);
  // Walk both: each fitted move ends exactly on an original point; the original points it
  // replaced must lie within the tolerance of its arc.
  ASSERT_EQ(fitted.moves.front().end, poly.moves.front().end);
  std::size_t k = 0;
  for (std::size_t i = 1; i < fitted.moves.size(); ++i) {
    const Move& m = fitted.moves[i];
    std::size_t next = k + 1;
    while (next < poly.moves.size() && !(poly.moves[next].end == m.end))
      ++next;
    ASSERT_LT(next, poly.moves.size());
    if (m.is_arc()) {
      const double r = distance(m.end.xy(), m.center.xy());
      EXPECT_GE(next - k, static_cast<std::size_t>(opt.min_points));
      for (std::size_t d = k + 1; d < next; ++d) {
        EXPECT_LE(std::abs(distance(poly.moves[d].end.xy(), m.center.xy()) - r), opt.tolerance_mm);
      }
    } else {
      EXPECT_EQ(next, k + 1);
    }
    k = next;
  }
  EXPECT_EQ(k, poly.moves.size() - 1);
}

TEST(PostprocessFitArcs, RejectsWhatIsNoArc) {
  // A square: corners are not arcs.
  Toolpath sq;
  sq.rapid_to({0, 0, 0});
  for (int rep = 0; rep < 3; ++rep) {
    sq.feed_to({10, 0, 0}, 500);
    sq.feed_to({10, 10, 0}, 500);
    sq.feed_to({0, 10, 0}, 500);
    sq.feed_to({0, 0, 0}, 500);
  }
  EXPECT_EQ(fit_arcs(sq).moves.size(), sq.moves.size());
  // Zig-zag between points of one circle: they fit the circle but do not advance along it.
  Toolpath zig;
  zig.rapid_to({10, 0, 0});
  for (int i = 1; i <= 12; ++i) {
    const double a = (i % 2 ? 0.3 : 0.1) * i;
    zig.feed_to({10 * std::cos(a), 10 * std::sin(a), 0}, 500);
  }
  for (const Move& m : fit_arcs(zig).moves)
    EXPECT_FALSE(m.is_arc());
  // Too few lines, too large a radius, changing height, or a feed change in the middle.
  ArcFitOptions opt;
  const Toolpath short_arc = polygon_circle(3 * 36, 10.0, false);
  Toolpath three;
  three.moves.assign(short_arc.moves.begin(), short_arc.moves.begin() + 4);  // 3 lines
  for (const Move& m : fit_arcs(three, opt).moves)
    EXPECT_FALSE(m.is_arc());
  opt.max_radius_mm = 5.0;
  for (const Move& m : fit_arcs(short_arc, opt).moves)
    EXPECT_FALSE(m.is_arc());
  Toolpath ramp = polygon_circle(36, 10.0, false);
  for (std::size_t i = 0; i < ramp.moves.size(); ++i)
    ramp.moves[i].end.z = -0.01 * i;
  for (const Move& m : fit_arcs(ramp).moves)
    EXPECT_FALSE(m.is_arc());
  Toolpath feeds = polygon_circle(8, 10.0, false);
  for (std::size_t i = 0; i < feeds.moves.size(); ++i)
    feeds.moves[i].feed_mm_min = 100.0 + i;
  for (const Move& m : fit_arcs(feeds).moves)
    EXPECT_FALSE(m.is_arc());
}

TEST(PostprocessSimplifyToolpath, MergesRunsOfSameKindFeedAndFlag) {
  Toolpath p;
  p.rapid_to({0, 0, 5});
  p.rapid_to({10, 0, 5});
  p.rapid_to({20, 0, 5});
  p.plunge_to(-1, 100);
  for (int i = 1; i <= 10; ++i)
    p.feed_to({20.0 + i, 0.001 * (i % 2), -1}, 600);  // wiggle
  for (int i = 1; i <= 10; ++i)
    p.feed_to({30.0, 1.0 * i, -1}, 300);  // new feed
  p.arc_to({30, 20, -1}, {30, 15}, false, 300);
  p.feed_to({30, 21, -1}, 300);
  p.feed_to({30, 22, -1}, 300);
  const Toolpath s = simplify(p, 0.01);
  ASSERT_EQ(s.moves.size(), 7u);
  EXPECT_EQ(s.moves[0].end, (Vec3{0, 0, 5}));  // first move kept as is
  EXPECT_EQ(s.moves[1].end, (Vec3{20, 0, 5}));
  EXPECT_EQ(s.moves[2].kind, MoveKind::kPlunge);
  EXPECT_EQ(s.moves[3].end, (Vec3{30, 0, -1}));
  EXPECT_EQ(s.moves[3].feed_mm_min, 600.0);
  EXPECT_EQ(s.moves[4].end, (Vec3{30, 10, -1}));
  EXPECT_EQ(s.moves[4].feed_mm_min, 300.0);
  EXPECT_EQ(s.moves[5].kind, MoveKind::kArc);
  EXPECT_EQ(s.moves[6].end, (Vec3{30, 22, -1}));
  // A tolerance below the wiggle keeps every wiggle point.
  EXPECT_EQ(simplify(p, 0.0001).moves.size(),
            p.moves.size() - 11);  // 1 rapid, 9 + 1 collinear feeds
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// A CL line across a wall: 0 up to x* = 1.2345, then a rim arc of radius 4 rising from z = 5
// (the ball resting on the rim of a wall 4 mm away), sampled every 0.1 mm. The refined line
// finds the jump to within 4 um and follows the arc, so the straight moves between its points
// stay within the tolerance of the true CL everywhere off the jump; a gentle line is left alone.
TEST(PostprocessSteepStretches, AJumpBecomesAStepAFewMicrometresWide) {
  const double xs = 1.2345;
  auto cl = [&](double x) {
    if (x < xs) return 0.0;
    const double d = 4.0 - (x - xs);  // horizontal distance to the rim
    return 5.0 + std::sqrt(std::max(0.0, 16.0 - d * d));
  };
  std::vector<Vec3> line;
  for (int k = 0; k <= 30; ++k)
    line.push_back({0.1 * k, 0.0, cl(0.1 * k)});
  int evals = 0;
  const double tol = 0.001;
  const std::vector<Vec3> out = refine_steep_stretches(line, tol, [&](Vec2 p) {
    ++evals;
    return cl(p.x);
  });
  ASSERT_GT(out.size(), line.size());
  EXPECT_EQ(out.front(), line.front());
  EXPECT_EQ(out.back(), line.back());
  double widest_jump = 0.0, worst = 0.0;
  for (std::size_t k = 0; k + 1 < out.size(); ++k) {
    ASSERT_LT(out[k].x, out[k + 1].x);
    if (out[k].x < xs && out[k + 1].x >= xs) widest_jump = out[k + 1].x - out[k].x;
    // Off the jump, the chord against the true CL at 50 points.
    if (out[k].x >= xs || out[k + 1].x < xs)
      for (int q = 1; q < 50; ++q) {
        const double x = out[k].x + (out[k + 1].x - out[k].x) * q / 50.0;
        const double z = out[k].z + (out[k + 1].z - out[k].z) * q / 50.0;
        worst = std::max(worst, cl(x) - z);
      }
  }
  EXPECT_LE(widest_jump, 0.004);
  EXPECT_LE(worst, 0.02);  // vertically, where the arc is nearly vertical: normal error < tol
  EXPECT_LT(evals, 200);
  // Without refinement the move across the jump spans the whole 0.1 mm step.
  std::vector<Vec3> gentle;
  for (int k = 0; k <= 30; ++k)
    gentle.push_back({0.1 * k, 0.0, 0.5 * std::sin(0.1 * k)});
  EXPECT_EQ(refine_steep_stretches(gentle, tol, [](Vec2) { return 0.0; }), gentle);
}

}  // namespace
}  // namespace swarf
