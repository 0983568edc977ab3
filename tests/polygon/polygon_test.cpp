#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "swarf/polygon/polygon.h"

namespace swarf {
namespace {

Ring rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}
PolygonSet rect_set(double x0, double y0, double x1, double y1) {
  return {{rect(x0, y0, x1, y1)}};
}
Ring circle(Vec2 c, double r, int n) {
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    ring.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return ring;
}
// Area of a regular n-gon inscribed in a circle of radius r.
double ngon_area(double r, int n) {
  return 0.5 * n * r * r * std::sin(2.0 * kPi / n);
}

// One grid step of snapping moves each vertex by at most 0.5e-5 mm; over a perimeter P the
// area can change by about P * 1e-5.
double snap_tolerance(double perimeter_mm) {
  return perimeter_mm * kPolygonResolutionMm;
}

TEST(Polygon, SignedAreaFollowsOrientation) {
  Ring r = rect(0, 0, 3, 2);
  EXPECT_DOUBLE_EQ(signed_area(r), 6.0);
  std::reverse(r.begin(), r.end());
  EXPECT_DOUBLE_EQ(signed_area(r), -6.0);
}

TEST(Polygon, NormalizedOrientsOutersCcwAndHolesCw) {
  Ring outer = rect(0, 0, 10, 10);
  std::reverse(outer.begin(), outer.end());  // given clockwise
  const Ring hole = rect(3, 3, 7, 7);        // given counter-clockwise
  const PolygonSet n = normalized({{outer, hole}}, FillRule::kEvenOdd);
  ASSERT_EQ(n.rings.size(), 2u);
  int outers = 0, holes = 0;
  for (const Ring& r : n.rings) {
    if (signed_area(r) > 0) {
      ++outers;
      EXPECT_DOUBLE_EQ(signed_area(r), 100.0);
    } else {
      ++holes;
      EXPECT_DOUBLE_EQ(signed_area(r), -16.0);
    }
  }
  EXPECT_EQ(outers, 1);
  EXPECT_EQ(holes, 1);
  EXPECT_DOUBLE_EQ(area(n), 84.0);
}

TEST(Polygon, FillRulesDifferOnNestedSameOrientation) {
  // Two nested CCW squares: even-odd makes a ring, non-zero the full outer square.
  const PolygonSet s{{rect(0, 0, 10, 10), rect(3, 3, 7, 7)}};
  EXPECT_DOUBLE_EQ(area(normalized(s, FillRule::kEvenOdd)), 84.0);
  EXPECT_DOUBLE_EQ(area(normalized(s, FillRule::kNonZero)), 100.0);
  // Positive keeps only counter-clockwise winding.
  Ring cw = rect(20, 0, 22, 2);
  std::reverse(cw.begin(), cw.end());
  const PolygonSet t{{rect(0, 0, 1, 1), cw}};
  EXPECT_DOUBLE_EQ(area(normalized(t, FillRule::kPositive)), 1.0);
  EXPECT_DOUBLE_EQ(area(normalized(t, FillRule::kNonZero)), 5.0);
}

TEST(Polygon, SelfIntersectingBowtieIsResolved) {
  // A bow-tie: two triangles of area 1 each with opposite orientations.
  const PolygonSet bowtie{{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}}};
  const PolygonSet n = normalized(bowtie, FillRule::kEvenOdd);
  ASSERT_EQ(n.rings.size(), 2u);
  for (const Ring& r : n.rings)
    EXPECT_NEAR(signed_area(r), 1.0, 1e-9);
}

TEST(Polygon, BooleansOfOverlappingRectangles) {
  const PolygonSet a = rect_set(0, 0, 4, 3);  // area 12
  const PolygonSet b = rect_set(2, 1, 7, 5);  // area 20, overlap [2,4]x[1,3] = 4
  EXPECT_DOUBLE_EQ(area(unite(a, b)), 28.0);
  EXPECT_DOUBLE_EQ(area(intersect(a, b)), 4.0);
  EXPECT_DOUBLE_EQ(area(subtract(a, b)), 8.0);
  EXPECT_DOUBLE_EQ(area(subtract(b, a)), 16.0);
  EXPECT_EQ(unite(a, b).rings.size(), 1u);
  EXPECT_TRUE(intersect(a, rect_set(10, 10, 11, 11)).empty());
}

TEST(Polygon, SubtractingInteriorMakesClockwiseHole) {
  const PolygonSet d = subtract(rect_set(0, 0, 10, 10), rect_set(2, 2, 5, 6));
  ASSERT_EQ(d.rings.size(), 2u);
  EXPECT_DOUBLE_EQ(area(d), 100.0 - 12.0);
  double hole_area = 0;
  for (const Ring& r : d.rings)
    if (signed_area(r) < 0) hole_area = signed_area(r);
  EXPECT_DOUBLE_EQ(hole_area, -12.0);
}

TEST(Polygon, ManySetUnionAndIntersection) {
  // A row of unit squares overlapping by half: union length 0.5 * (n + 1).
  std::vector<PolygonSet> sets;
  const int n = 50;
  for (int i = 0; i < n; ++i)
    sets.push_back(rect_set(0.5 * i, 0, 0.5 * i + 1, 1));
  EXPECT_NEAR(area(unite(sets)), 0.5 * (n + 1), 1e-9);
  EXPECT_EQ(unite(sets).rings.size(), 1u);

  // Nested intersection of [0, 10 - i] squares is the smallest one.
  std::vector<PolygonSet> nested;
  for (int i = 0; i < 5; ++i)
    nested.push_back(rect_set(i, 0, 10, 10 - i));
  EXPECT_DOUBLE_EQ(area(intersect(nested)), 6.0 * 6.0);
  nested.push_back(rect_set(20, 20, 21, 21));
  EXPECT_TRUE(intersect(nested).empty());
  EXPECT_TRUE(intersect(std::span<const PolygonSet>{}).empty());
  EXPECT_TRUE(unite(std::span<const PolygonSet>{}).empty());
}

TEST(Polygon, UnionOfSetWithHoleAndIslandKeepsBoth) {
  // A frame (square with hole) and an island inside the hole.
  const PolygonSet frame = subtract(rect_set(0, 0, 10, 10), rect_set(2, 2, 8, 8));
  const PolygonSet island = rect_set(4, 4, 6, 6);
  const std::vector<PolygonSet> sets{frame, island};
  const PolygonSet u = unite(sets);
  EXPECT_DOUBLE_EQ(area(u), 100.0 - 36.0 + 4.0);
  EXPECT_TRUE(contains(u, {5, 5}));
  EXPECT_FALSE(contains(u, {3, 3}));
  EXPECT_TRUE(contains(u, {1, 1}));
}

TEST(Polygon, OffsetOfSquareMatchesMinkowskiSum) {
  // Growing an s x s square by r: s^2 + 4 s r + pi r^2 (the rounded corners are polygonal
  // arcs inscribed within arc_tolerance, so they can only lose area, at most about the
  // tolerance times the arc length).
  const double s = 10.0, r = 2.0, tol = 0.001;
  const PolygonSet grown = offset(rect_set(0, 0, s, s), r, {.arc_tolerance_mm = tol});
  const double exact = s * s + 4 * s * r + kPi * r * r;
  const double got = area(grown);
  EXPECT_LE(got, exact + snap_tolerance(60));
  EXPECT_GE(got, exact - 2.0 * kPi * r * tol - snap_tolerance(60));
  ASSERT_EQ(grown.rings.size(), 1u);
  EXPECT_GT(signed_area(grown.rings[0]), 0.0);
  const Box2 b = bounds(grown);
  EXPECT_NEAR(b.min.x, -r, 1e-5);
  EXPECT_NEAR(b.max.y, s + r, 1e-5);
  // Every vertex lies within [r - tol, r] of the square (up to grid snapping).
  const PolygonSet square = rect_set(0, 0, s, s);
  for (const Vec2& p : grown.rings[0]) {
    const double d = distance_to_boundary(square, p);
    EXPECT_LE(d, r + 1e-5);
    EXPECT_GE(d, r - tol - 1e-5);
  }
}

TEST(Polygon, ArcToleranceIsInMillimetres) {
  // A coarse tolerance must give visibly fewer vertices than a fine one, and the area
  // deficit of the rounded corners must stay within the requested tolerance.
  const double r = 5.0;
  const PolygonSet fine = offset(rect_set(0, 0, 1, 1), r, {.arc_tolerance_mm = 0.0005});
  const PolygonSet coarse = offset(rect_set(0, 0, 1, 1), r, {.arc_tolerance_mm = 0.05});
  ASSERT_EQ(fine.rings.size(), 1u);
  ASSERT_EQ(coarse.rings.size(), 1u);
  EXPECT_GT(fine.rings[0].size(), 3 * coarse.rings[0].size());
  // For a chord with sagitta t on radius r, n ~ pi / acos(1 - t / r) vertices per full turn.
  const double expected_coarse = kPi / std::acos(1.0 - 0.05 / r);
  EXPECT_NEAR(static_cast<double>(coarse.rings[0].size()), expected_coarse + 4, 6.0);
  const double exact = 1 + 4 * r + kPi * r * r;
  EXPECT_NEAR(area(coarse), exact, 2 * kPi * r * 0.05);
  EXPECT_LT(area(coarse), exact);
}

TEST(Polygon, OffsetOfCirclePolygon) {
  // Offsetting a convex polygon outwards by r adds r * perimeter + pi r^2 (Steiner).
  const Ring c = circle({3, -2}, 10.0, 720);
  const PolygonSet set{{c}};
  const double a0 = area(set), p0 = perimeter(set);
  EXPECT_NEAR(a0, ngon_area(10.0, 720), 1e-6);
  const double r = 1.5;
  const PolygonSet grown = offset(set, r, {.arc_tolerance_mm = 0.0005});
  EXPECT_NEAR(area(grown), a0 + r * p0 + kPi * r * r, 0.01);
  // Shrinking by r: the inner parallel polygon of a regular n-gon is the n-gon with
  // apothem reduced by r.
  const PolygonSet shrunk = offset(set, -r);
  const double apothem = 10.0 * std::cos(kPi / 720) - r;
  const double inner_area = 720 * apothem * apothem * std::tan(kPi / 720);
  EXPECT_NEAR(area(shrunk), inner_area, snap_tolerance(2 * kPi * 10));
}

// Douglas-Peucker on rings: every dropped vertex stays within the tolerance of the ring that
// is kept (so the boundary moves by at most that much), the kept vertices are original ones,
// and a finely faceted circle keeps about one vertex in sqrt(tolerance / sagitta).
TEST(Polygon, SimplifiedRingsStayWithinTheTolerance) {
  const Ring c = circle({1, 2}, 10.0, 2000);  // edges 31 um long, sagitta 0.012 um
  const PolygonSet square_with_hole = subtract(rect_set(-20, -20, 20, 20), PolygonSet{{c}});
  for (const double tol : {0.0002, 0.001, 0.005}) {
    const PolygonSet s = simplified(square_with_hole, tol);
    ASSERT_EQ(s.rings.size(), 2u);
    std::size_t kept = 0;
    for (const Ring& r : s.rings) {
      if (r.size() == 4) continue;  // the square keeps its corners
      kept = r.size();
      for (const Vec2& v : r) {  // original vertices only
        const double rad = norm(v - Vec2{1, 2});
        EXPECT_NEAR(rad, 10.0, 1e-5);
      }
      // Each original vertex lies within tol (plus Clipper's grid) of the kept ring.
      for (const Vec2& v : c) {
        double d = 1e9;
        for (std::size_t k = 0; k < r.size(); ++k) {
          const Vec2 a = r[k], e = r[(k + 1) % r.size()] - a;
          const double t = std::clamp(dot(v - a, e) / norm_sq(e), 0.0, 1.0);
          d = std::min(d, norm(a + e * t - v));
        }
        ASSERT_LE(d, tol + 1e-5) << tol;
      }
    }
    // Sagitta of a kept chord L is L^2 / (8 R) <= tol: at least 2 pi R / sqrt(8 R tol) chords.
    const double chords = 2.0 * kPi * 10.0 / std::sqrt(8.0 * 10.0 * tol);
    EXPECT_GE(static_cast<double>(kept), chords * 0.99) << tol;
    EXPECT_LE(static_cast<double>(kept), 2.5 * chords) << tol;
    EXPECT_NEAR(area(s), area(square_with_hole), perimeter(square_with_hole) * tol);
  }
  EXPECT_EQ(simplified(square_with_hole, 0.0).rings, square_with_hole.rings);
}

TEST(Polygon, ShrinkThenGrowRemovesNarrowPartsAndRestoresWideOnes) {
  // Two 10x10 squares joined by a 1 mm wide bridge: opening by 1 mm removes the bridge.
  PolygonSet shape = unite(rect_set(0, 0, 10, 10), rect_set(20, 0, 30, 10));
  shape = unite(shape, rect_set(10, 4.5, 20, 5.5));
  ASSERT_EQ(connected_parts(shape).size(), 1u);
  const PolygonSet opened = offset(offset(shape, -1.0), 1.0);
  EXPECT_EQ(connected_parts(opened).size(), 2u);
  // Each square alone comes back with rounded corners, losing (4 - pi) r^2 each; where the
  // bridge met a square, a small bump survives, so the opened shape lies between the two
  // opened squares and the shape without its bridge.
  const double squares_opened = 2 * (100 - (4 - kPi) * 1.0);
  EXPECT_GE(area(opened), squares_opened - 0.01);
  EXPECT_LE(area(opened), 200.0);
  // Grid rounding may leave slivers one grid step wide along the boundary.
  EXPECT_LT(area(subtract(opened, shape)), snap_tolerance(perimeter(shape)));
}

TEST(Polygon, OpeningASquareRoundsItsCorners) {
  const double s = 10.0, r = 1.5;
  const PolygonSet opened = offset(offset(rect_set(0, 0, s, s), -r), r);
  EXPECT_NEAR(area(opened), s * s - (4 - kPi) * r * r, 0.01);
  EXPECT_NEAR(perimeter(opened), 4 * (s - 2 * r) + 2 * kPi * r, 0.01);
}

TEST(Polygon, ShrinkingAwayGivesEmpty) {
  EXPECT_TRUE(offset(rect_set(0, 0, 2, 2), -1.01).empty());
  EXPECT_FALSE(offset(rect_set(0, 0, 2, 2), -0.99).empty());
}

TEST(Polygon, OffsetOfHoleGrowsInward) {
  // A square with a square hole grown by 1: the outer grows, the hole shrinks (the hole's
  // corners stay sharp since they are concave for the region).
  const PolygonSet frame = subtract(rect_set(0, 0, 20, 20), rect_set(5, 5, 15, 15));
  const PolygonSet g = offset(frame, 1.0);
  const double outer = 22 * 22 - (4 - kPi);
  const double hole = 8 * 8;
  EXPECT_NEAR(area(g), outer - hole, 0.01);
}

TEST(Polygon, InflatedSegmentIsStadium) {
  const double r = 1.25, len = 7.0, tol = 0.001;
  const std::vector<Polyline2> lines{{{1, 1}, {1 + len, 1}}};
  const PolygonSet s = inflate_polylines(lines, r, {.arc_tolerance_mm = tol});
  const double exact = 2 * r * len + kPi * r * r;
  EXPECT_LE(area(s), exact + snap_tolerance(30));
  EXPECT_GE(area(s), exact - 2 * kPi * r * tol);
  ASSERT_EQ(s.rings.size(), 1u);
  EXPECT_TRUE(contains(s, {1 - r + 0.01, 1}));
  EXPECT_FALSE(contains(s, {1, 1 + r + 0.01}));
}

TEST(Polygon, InflatedPointIsDiskAndOverlapsAreUnited) {
  const std::vector<Polyline2> pts{{{0, 0}}, {{1, 0}, {1, 0}}};
  const PolygonSet s = inflate_polylines(pts, 2.0, {.arc_tolerance_mm = 0.0001});
  // Lens union of two disks of radius 2 at distance 1: 2 pi r^2 - lens overlap.
  const double r = 2.0, d = 1.0;
  const double lens = 2 * r * r * std::acos(d / (2 * r)) - 0.5 * d * std::sqrt(4 * r * r - d * d);
  EXPECT_NEAR(area(s), 2 * kPi * r * r - lens, 0.005);
  EXPECT_EQ(s.rings.size(), 1u);
}

TEST(Polygon, PointInPolygonWithHole) {
  const PolygonSet ring = subtract(rect_set(0, 0, 10, 10), rect_set(3, 3, 7, 7));
  EXPECT_TRUE(contains(ring, {1, 1}));
  EXPECT_TRUE(contains(ring, {8, 5}));
  EXPECT_FALSE(contains(ring, {5, 5}));     // in the hole
  EXPECT_FALSE(contains(ring, {11, 5}));    // outside
  EXPECT_FALSE(contains(ring, {-0.1, 5}));  // just outside
  EXPECT_TRUE(contains(ring, {0, 5}));      // outer boundary counts as inside
  EXPECT_TRUE(contains(ring, {3, 5}));      // hole boundary counts as inside
  EXPECT_TRUE(contains(ring, {10, 10}));    // a corner
  EXPECT_FALSE(contains(ring, {3.001, 5}));
  // Brute-force check against the analytic region on a grid of points.
  for (double x = -1.05; x < 11; x += 0.5)
    for (double y = -1.05; y < 11; y += 0.5) {
      const bool in_outer = x >= 0 && x <= 10 && y >= 0 && y <= 10;
      const bool in_hole = x > 3 && x < 7 && y > 3 && y < 7;
      EXPECT_EQ(contains(ring, {x, y}), in_outer && !in_hole) << x << ", " << y;
    }
}

TEST(Polygon, DistanceToBoundaryOfRectangle) {
  const PolygonSet r = rect_set(0, 0, 10, 4);
  EXPECT_DOUBLE_EQ(distance_to_boundary(r, {5, 2}), 2.0);
  EXPECT_DOUBLE_EQ(distance_to_boundary(r, {1, 2}), 1.0);
  EXPECT_DOUBLE_EQ(distance_to_boundary(r, {15, 2}), 5.0);
  EXPECT_DOUBLE_EQ(distance_to_boundary(r, {13, 8}), 5.0);  // to the corner (10, 4)
  EXPECT_DOUBLE_EQ(distance_to_boundary(r, {0, 3}), 0.0);
}

TEST(Polygon, ConnectedPartsSplitsIslandsFromHoles) {
  // Frame with an island in its hole, and a separate square: three parts, the frame
  // keeps its hole.
  PolygonSet s = subtract(rect_set(0, 0, 10, 10), rect_set(2, 2, 8, 8));
  s = unite(s, rect_set(4, 4, 6, 6));
  s = unite(s, rect_set(20, 0, 21, 1));
  const std::vector<PolygonSet> parts = connected_parts(s);
  ASSERT_EQ(parts.size(), 3u);
  double total = 0;
  int with_hole = 0;
  for (const PolygonSet& p : parts) {
    total += area(p);
    EXPECT_GT(signed_area(p.rings.front()), 0.0);
    for (std::size_t i = 1; i < p.rings.size(); ++i)
      EXPECT_LT(signed_area(p.rings[i]), 0.0);
    if (p.rings.size() == 2) {
      ++with_hole;
      EXPECT_DOUBLE_EQ(area(p), 64.0);
    }
  }
  EXPECT_EQ(with_hole, 1);
  EXPECT_DOUBLE_EQ(total, area(s));
}

TEST(Polygon, BoundsAndPerimeter) {
  const PolygonSet s = subtract(rect_set(-1, -2, 3, 4), rect_set(0, 0, 1, 1));
  const Box2 b = bounds(s);
  EXPECT_EQ(b.min, (Vec2{-1, -2}));
  EXPECT_EQ(b.max, (Vec2{3, 4}));
  EXPECT_DOUBLE_EQ(perimeter(s), 2 * (4 + 6) + 4);
  EXPECT_TRUE(bounds(PolygonSet{}).empty());
}

TEST(Polygon, CoordinatesSnapToResolutionGrid) {
  const PolygonSet s = normalized(rect_set(0.123456789, 0, 1, 1));
  const Box2 b = bounds(s);
  EXPECT_DOUBLE_EQ(b.min.x, 0.12346);
  // Rings collapsing below the grid are dropped.
  EXPECT_TRUE(normalized(rect_set(0, 0, 1e-7, 1e-7)).empty());
}

TEST(Polygon, DegenerateAndNonFiniteInputs) {
  EXPECT_TRUE(normalized(PolygonSet{{{{0, 0}, {1, 1}}}}).empty());
  const double nan = std::nan("");
  const PolygonSet s{{{{0, 0}, {nan, 0}, {2, 0}, {2, 2}, {0, 2}}}};
  EXPECT_DOUBLE_EQ(area(normalized(s)), 4.0);
  EXPECT_DOUBLE_EQ(area(offset(rect_set(0, 0, 1, 1), nan)), 1.0);
  EXPECT_TRUE(inflate_polylines(std::vector<Polyline2>{{{0, 0}, {1, 0}}}, -1.0).empty());
}

}  // namespace
}  // namespace swarf
