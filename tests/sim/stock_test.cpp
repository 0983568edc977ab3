// Material removal on the tri-slice stock against closed-form volumes at ds = 0.1 mm.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/sections.h"
#include "swarf/mesh/generate.h"
#include "swarf/sim/stock.h"

namespace swarf::sim {
namespace {

constexpr double kPitch = 0.1;

Stock block() {
  auto s = Stock::block({{0, 0, 0}, {60, 40, 20}}, kPitch);
  EXPECT_TRUE(s.ok());
  return std::move(s).value();
}

ToolSolid flat(double d) {
  return {d / 2, 0.0};
}
ToolSolid ball(double d) {
  return {d / 2, d / 2};
}

void expect_volume(const Removal& r, double want) {
  EXPECT_NEAR(r.volume_mm3, want, 0.005 * want);
  // Each family alone is also close on these cuts.
  for (double v : r.by_family_mm3)
    EXPECT_NEAR(v, want, 0.01 * want);
}

TEST(StockRemoval, BlockVolumeIsExact) {
  const Stock s = block();
  EXPECT_NEAR(s.volume_mm3(), 60.0 * 40 * 20, 1e-6);
  EXPECT_NEAR(s.volume_mm3(Axis::kX), 60.0 * 40 * 20, 1e-6);
  EXPECT_TRUE(s.inside({1, 1, 1}, EngagementRule::kMajority));
  EXPECT_FALSE(s.inside({1, 1, 20.04}, EngagementRule::kMajority));
  EXPECT_FALSE(s.inside({-0.01, 1, 1}, EngagementRule::kAny));
}

TEST(StockRemoval, BlockOffThePitchGridKeepsItsVolume) {
  // 10.05 mm tall at a 0.1 mm pitch: the top cell is half a pitch thick.
  auto s = Stock::block({{0, 0, 0}, {10.05, 5.03, 10.05}}, kPitch);
  ASSERT_TRUE(s.ok());
  const double v = 10.05 * 5.03 * 10.05;
  EXPECT_NEAR(s->volume_mm3(), v, 1e-9 * v);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(s->volume_mm3(static_cast<Axis>(a)), v, 1e-9 * v);
  EXPECT_FALSE(s->inside({5, 2, 10.07}, EngagementRule::kAny));
  // Facing off the top 0.55 mm with a big flat end mill.
  const Vec3 tips[2] = {{-20, 2.5, 9.5}, {30, 2.5, 9.5}};
  const Removal rm = s->remove(flat(40), tips);
  expect_volume(rm, 10.05 * 5.03 * 0.55);
}

TEST(StockRemoval, FlatSlot) {
  Stock s = block();
  const double r = 5, len = 30, depth = 2;
  const Vec3 tips[2] = {{10, 20, 20 - depth}, {10 + len, 20, 20 - depth}};
  const double before = s.volume_mm3();
  const Removal rm = s.remove(flat(2 * r), tips);
  const double want = depth * (2 * r * len + kPi * r * r);  // stadium times depth
  expect_volume(rm, want);
  EXPECT_NEAR(before - s.volume_mm3(), rm.volume_mm3, 1e-6 * want);
  // The slot floor is now air, the wall beside it still material.
  EXPECT_FALSE(s.inside({25, 20, 18.5}, EngagementRule::kMajority));
  EXPECT_TRUE(s.inside({25, 26, 18.5}, EngagementRule::kMajority));
}

TEST(StockRemoval, BallSlotShallowerThanRadius) {
  Stock s = block();
  const double r = 4, len = 20, d = 2.5;
  const Vec3 tips[2] = {{12, 15, 20 - d}, {12, 15 + len, 20 - d}};
  const Removal rm = s.remove(ball(2 * r), tips);
  // Circular segment of depth d along the slot plus a spherical cap at the two ends.
  const double seg = r * r * std::acos((r - d) / r) - (r - d) * std::sqrt(2 * r * d - d * d);
  const double cap = kPi * d * d * (3 * r - d) / 3.0;
  expect_volume(rm, len * seg + cap);
}

TEST(StockRemoval, FlatRampFromTheTopFace) {
  Stock s = block();
  const double r = 5, len = 30, drop = 2;
  const Vec3 tips[2] = {{10, 20, 20}, {10 + len, 20, 20 - drop}};
  const Removal rm = s.remove(flat(2 * r), tips);
  // Per line y = const: a triangle under the ramp (len * drop / 2) and the full-depth end
  // disk's chord (2 s * drop); integrated over the tool width.
  const double want = len * drop / 2 * 2 * r + drop * 2 * (kPi * r * r / 2);
  expect_volume(rm, want);
}

TEST(StockRemoval, BallRampEnteringFromTheAir) {
  // A ball ramping from above the stock into it: checked against a direct integration of
  // the depth under the top face, depth(x, y) = 20 - min over t of (z(t) + H(rho)), with H
  // the ball's height at distance rho from its axis (convex in t: ternary search).
  Stock s = block();
  const double r = 4;
  const Vec3 a{10, 20, 21}, b{40, 20, 17};
  const Vec3 tips[2] = {a, b};
  const Removal rm = s.remove(ball(2 * r), tips);
  double want = 0.0;
  const double h = 0.05;
  for (double x = 5 + h / 2; x < 46; x += h) {
    for (double y = 15.5 + h / 2; y < 24.5; y += h) {
      auto zt = [&](double t) {
        const double cx = a.x + (b.x - a.x) * t, cz = a.z + (b.z - a.z) * t;
        const double rho = std::hypot(x - cx, y - 20);
        return rho >= r ? 1e9 + rho : cz + r - std::sqrt(r * r - rho * rho);
      };
      double lo = 0, hi = 1;
      for (int k = 0; k < 50; ++k) {
        const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        if (zt(m1) < zt(m2)) {
          hi = m2;
        } else {
          lo = m1;
        }
      }
      const double zl = std::min({zt(0.0), zt(1.0), zt(0.5 * (lo + hi))});
      if (zl < 20) want += (20 - zl) * h * h;
    }
  }
  expect_volume(rm, want);
}

TEST(StockRemoval, CircularPocket) {
  Stock s = block();
  const double r = 5, ring = 6, depth = 3;
  const Vec3 c{30, 20, 20 - depth};
  std::vector<Vec3> tips = {c + Vec3{0, 0, depth}, c};  // plunge at the centre
  tips.push_back(c + Vec3{ring, 0, 0});
  const int n = 377;  // chords of 0.1 mm
  for (int i = 1; i <= n; ++i) {
    const double a = 2 * kPi * i / n;
    tips.push_back(c + Vec3{ring * std::cos(a), ring * std::sin(a), 0});
  }
  const Removal rm = s.remove(flat(2 * r), tips);
  expect_volume(rm, kPi * (ring + r) * (ring + r) * depth);
}

TEST(StockRemoval, BullNoseSlot) {
  Stock s = block();
  const double r = 5, rc = 2, len = 20, d = 3;
  const Vec3 tips[2] = {{15, 10, 20 - d}, {15 + len, 10 + len, 20 - d}};  // diagonal
  const Removal rm = s.remove(ToolSolid{r, rc}, tips);
  // Section through the axis: a d-deep rectangle 2r wide less two corner spandrels; the two
  // ends together make the tool's own solid below depth d, its corner ring by Pappus.
  const double spandrel = rc * rc * (1 - kPi / 4);
  const double section = 2 * r * d - 2 * spandrel;
  const double centroid_r = r - rc + rc / (6 - 1.5 * kPi);
  const double solid = kPi * r * r * d - 2 * kPi * centroid_r * spandrel;
  const double want = len * std::sqrt(2.0) * section + solid;
  EXPECT_NEAR(rm.volume_mm3, want, 0.005 * want);
}

TEST(StockRemoval, SecondPassRemovesNothing) {
  Stock s = block();
  const Vec3 tips[2] = {{10, 20, 18}, {40, 20, 18}};
  s.remove(ball(8), tips);
  const Removal again = s.remove(ball(8), tips);
  EXPECT_LT(again.volume_mm3, 1e-6);
}

TEST(StockRemoval, MeshStockMatchesItsVolume) {
  // A 64-sided prism: its exact volume is the polygon area times the height.
  const Mesh m = make_cylinder({20, 20, 0}, 10.0, 15.0, 64);
  const auto s = Stock::from_mesh(m, kPitch);
  ASSERT_TRUE(s.ok()) << s.status().to_string();
  const double want = 0.5 * 64 * 100.0 * std::sin(2 * kPi / 64) * 15.0;
  EXPECT_NEAR(s->volume_mm3(), want, 0.005 * want);
  EXPECT_TRUE(s->inside({20, 20, 7}, EngagementRule::kMajority));
  EXPECT_FALSE(s->inside({29.99, 29.99, 7.5}, EngagementRule::kMajority));  // 14 mm out
}

TEST(StockRemoval, MajorityVoteResolvesAFloorBetweenSlices) {
  // A floor at z = 18.07 lies between the xy slices at 18.05 (below it, still material) and
  // 18.15 (cut away). A point 0.01 above the floor is nearest to the 18.05 slice, so the xy
  // family alone (and the paper's any-family rule) calls it material; the yz and zx slices
  // cut the floor exactly and outvote it.
  Stock s = block();
  const Vec3 tips[2] = {{10, 20, 18.07}, {40, 20, 18.07}};
  s.remove(flat(10), tips);
  const Vec3 p{25, 20, 18.08};
  EXPECT_TRUE(s.inside(p, Axis::kZ));
  EXPECT_TRUE(s.inside(p, EngagementRule::kAny));
  EXPECT_FALSE(s.inside(p, EngagementRule::kMajority));
  EXPECT_TRUE(s.inside({25, 20, 18.06}, EngagementRule::kMajority));
}

TEST(Sections, ConvexHullOfSquareWithInnerPoints) {
  const Ring h = convex_hull({{0, 0}, {1, 0}, {0.5, 0.5}, {1, 1}, {0, 1}, {0.5, 0}});
  ASSERT_EQ(h.size(), 4u);
  EXPECT_NEAR(signed_area(h), 1.0, 1e-12);
}

TEST(Sections, BallSectionInSidePlaneIsItsCircle) {
  // A ball cut by a plane at distance d from its axis: a disk of radius sqrt(R^2 - d^2)
  // below the centre, then the shank's straight sides.
  const ToolSolid b = ball(8);
  std::vector<Vec2> pts;
  append_section_points(b, {0, 0, 0}, Axis::kX, 1.5, 10, pts);
  const Ring h = convex_hull(pts);
  const double rho = std::sqrt(16 - 1.5 * 1.5);
  const double want = kPi * rho * rho / 2 + 2 * rho * (10 - 4);
  EXPECT_NEAR(signed_area(h), want, 1e-3 * want);
}

}  // namespace
}  // namespace swarf::sim
