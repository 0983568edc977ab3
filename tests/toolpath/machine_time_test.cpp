// The acceleration-limited machine time against closed forms (lines, corners rounded by the
// arc within the junction deviation, arcs at their centripetal limit, helices) and against
// a brute-force reference that integrates the speed along the path in 2 um steps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "swarf/toolpath/metrics.h"
#include "swarf/toolpath/toolpath.h"

namespace swarf {
namespace {

// 100 mm/s, 1000 mm/s^2: speeding up or braking takes 5 mm and 0.1 s.
constexpr double kFeed = 6000.0, kSpeed = 100.0, kAccel = 1000.0;

MetricsOptions machine(double accel = kAccel, double deviation = 0.01) {
  MetricsOptions o;
  o.accel_mm_s2 = accel;
  o.junction_deviation_mm = deviation;
  return o;
}

Toolpath polyline(const std::vector<Vec3>& pts, double feed = kFeed) {
  Toolpath p;
  p.rapid_to(pts.front());  // the start: its length is not counted
  for (std::size_t k = 1; k < pts.size(); ++k)
    p.feed_to(pts[k], feed);
  return p;
}

// A leg of length len run from v0 up to the top speed v and down to v1: len / v plus, for
// each end, the time lost speeding up or braking, (v - v_end)^2 / (2 a v).
double leg(double len, double v0, double v1, double v = kSpeed, double a = kAccel) {
  return len / v + ((v - v0) * (v - v0) + (v - v1) * (v - v1)) / (2.0 * a * v);
}

TEST(MachineTime, LongLineAddsOneAccelerationTime) {
  const Toolpath p = polyline({{0, 0, 0}, {100, 0, 0}});
  EXPECT_NEAR(machine_time_s(p, machine()), 100.0 / kSpeed + kSpeed / kAccel, 1e-12);
  EXPECT_NEAR(compute_metrics(p, machine()).machining_time_s, 1.0, 1e-12);
}

TEST(MachineTime, ShortLineNeverReachesItsFeed) {
  // 4 mm is less than the 10 mm it takes to reach 100 mm/s and stop: a triangle.
  const Toolpath p = polyline({{0, 0, 0}, {0, 4, 0}});
  EXPECT_NEAR(machine_time_s(p, machine()), 2.0 * std::sqrt(4.0 / kAccel), 1e-12);
}

TEST(MachineTime, CollinearPiecesCostNothing) {
  std::vector<Vec3> pts;
  for (int k = 0; k <= 1000; ++k)
    pts.push_back({0.1 * k, 0.05 * k, -0.01 * k});
  const double len = norm(pts.back() - pts.front());
  EXPECT_NEAR(machine_time_s(polyline(pts), machine()), len / kSpeed + kSpeed / kAccel, 1e-9);
}

TEST(MachineTime, ReversalStops) {
  const Toolpath p = polyline({{0, 0, 0}, {50, 0, 0}, {0, 0, 0}});
  EXPECT_NEAR(machine_time_s(p, machine()), 2.0 * leg(50.0, 0.0, 0.0), 1e-12);
  EXPECT_NEAR(compute_metrics(p, machine()).machining_time_s, 1.0, 1e-12);
}

TEST(MachineTime, RightAngleTakenAtTheSpeedOfTheArcRoundingIt) {
  // The circle tangent to both legs of a right angle whose nearest point is d from the
  // corner: its centre lies on the bisector at R sqrt(2), so R (sqrt(2) - 1) = d.
  const double d = 0.05, radius = d / (std::sqrt(2.0) - 1.0);
  const double vj = std::sqrt(kAccel * radius);
  ASSERT_LT(vj, kSpeed);
  const Toolpath p = polyline({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}});
  EXPECT_NEAR(machine_time_s(p, machine(kAccel, d)), 2.0 * leg(100.0, 0.0, vj), 1e-12);
  // Exact stop (G61) when no deviation is allowed: two separate legs.
  EXPECT_NEAR(machine_time_s(p, machine(kAccel, 0.0)), 2.0 * leg(100.0, 0.0, 0.0), 1e-12);
}

TEST(MachineTime, NoAccelerationLimitIsTheFeedTime) {
  const Toolpath p = polyline({{0, 0, 0}, {10, 0, 0}, {0, 3, 0}, {5, 5, -1}});
  const ToolpathMetrics m = compute_metrics(p, machine(0.0));
  EXPECT_NEAR(m.machine_time_s, m.machining_time_s, 1e-12);
  EXPECT_GT(compute_metrics(p, machine()).machine_time_s, m.machining_time_s);
}

TEST(MachineTime, ArcNoFasterThanItsCentripetalAcceleration) {
  // A full circle of radius 2: v^2 / r = a at sqrt(2000) = 44.7 mm/s, under the feed.
  Toolpath p;
  p.rapid_to({2, 0, 0});
  p.arc_to({2, 0, 0}, {0, 0}, false, kFeed);
  const double top = std::sqrt(kAccel * 2.0);
  EXPECT_NEAR(machine_time_s(p, machine()), leg(4.0 * kPi, 0.0, 0.0, top), 1e-9);
}

TEST(MachineTime, HelixLimitedByItsTurningPartOnly) {
  // One turn of radius 2 down 3 mm: the speed's part in the plane, v * 4 pi / len, turns.
  Toolpath p;
  p.rapid_to({2, 0, 0});
  p.arc_to({2, 0, -3}, {0, 0}, true, kFeed);
  const double len = std::hypot(4.0 * kPi, 3.0);
  const double top = std::sqrt(kAccel * 2.0) * len / (4.0 * kPi);
  EXPECT_NEAR(machine_time_s(p, machine()), leg(len, 0.0, 0.0, top), 1e-9);
}

TEST(MachineTime, TangentArcJoinsItsLineWithoutSlowing) {
  // Along +x into a counter-clockwise quarter turn of radius 50 (centripetal limit 224
  // mm/s, over the feed): one smooth block of speed, accelerated and braked once.
  Toolpath p;
  p.rapid_to({-30, 0, 0});
  p.feed_to({0, 0, 0}, kFeed);
  p.arc_to({50, 50, 0}, {0, 50}, false, kFeed);
  p.feed_to({50, 80, 0}, kFeed);
  const double len = 60.0 + 25.0 * kPi;
  EXPECT_NEAR(machine_time_s(p, machine(kAccel, 0.0)), leg(len, 0.0, 0.0), 1e-9);
}

TEST(MachineTime, MovesWithNoFeedStopTheMachine) {
  Toolpath p = polyline({{0, 0, 0}, {50, 0, 0}});
  p.feed_to({50, 0, -1}, 0.0);  // no time of its own
  p.feed_to({100, 0, -1}, kFeed);
  EXPECT_NEAR(machine_time_s(p, machine()), 2.0 * leg(50.0, 0.0, 0.0), 1e-12);
}

// Brute force: every move cut into 2 um steps, each step's end no faster than its move's
// feed (or, at a junction, the rounding arc's speed), then the same speeds brought within
// reach of their neighbours step by step, and the time summed step by step at constant
// acceleration (2 ds / (v0 + v1)). Independent of the planner's per-move trapezoids.
double reference_time(const std::vector<Vec3>& pts, const std::vector<double>& feeds, double a,
                      double d) {
  constexpr double kStep = 0.002;
  std::vector<double> ds, vmax;
  vmax.push_back(0.0);
  for (std::size_t k = 1; k < pts.size(); ++k) {
    const double len = norm(pts[k] - pts[k - 1]), v = feeds[k - 1] / 60.0;
    const int n = std::max(1, static_cast<int>(std::ceil(len / kStep)));
    for (int q = 0; q < n; ++q) {
      ds.push_back(len / n);
      vmax.push_back(v);
    }
    if (k + 1 < pts.size()) {
      // The corner: inside angle from the two legs, the rounding arc's radius from it.
      const Vec3 u = (pts[k - 1] - pts[k]) / norm(pts[k - 1] - pts[k]);
      const Vec3 w = (pts[k + 1] - pts[k]) / norm(pts[k + 1] - pts[k]);
      const double half = 0.5 * std::acos(std::clamp(dot(u, w), -1.0, 1.0));
      const double radius = d * std::sin(half) / (1.0 - std::sin(half));
      vmax.back() = std::min({v, feeds[k] / 60.0, std::sqrt(a * radius)});
    } else {
      vmax.back() = 0.0;
    }
  }
  std::vector<double> v = vmax;
  for (std::size_t k = ds.size(); k-- > 0;)
    v[k] = std::min(v[k], std::sqrt(v[k + 1] * v[k + 1] + 2.0 * a * ds[k]));
  for (std::size_t k = 0; k < ds.size(); ++k)
    v[k + 1] = std::min(v[k + 1], std::sqrt(v[k] * v[k] + 2.0 * a * ds[k]));
  double t = 0.0;
  for (std::size_t k = 0; k < ds.size(); ++k)
    t += 2.0 * ds[k] / (v[k] + v[k + 1]);
  return t;
}

TEST(MachineTime, MatchesBruteForceOnRandomPolylines) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-20.0, 20.0), feed(300.0, 9000.0);
  for (int trial = 0; trial < 8; ++trial) {
    std::vector<Vec3> pts{{0, 0, 0}};
    std::vector<double> feeds;
    Toolpath p;
    p.rapid_to(pts.front());
    for (int k = 0; k < 12; ++k) {
      pts.push_back({coord(rng), coord(rng), 0.1 * coord(rng)});
      feeds.push_back(feed(rng));
      p.feed_to(pts.back(), feeds.back());
    }
    const double deviation = 0.02 * (trial + 1);
    const double got = machine_time_s(p, machine(kAccel, deviation));
    const double want = reference_time(pts, feeds, kAccel, deviation);
    EXPECT_NEAR(got, want, 2e-4 * want) << "trial " << trial;
    EXPECT_GT(got, compute_metrics(p, machine()).machining_time_s);
  }
}

}  // namespace
}  // namespace swarf
