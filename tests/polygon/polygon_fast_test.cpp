// detail::normalized_nonzero_fast must give the same region as normalized(kNonZero) on every
// input, valid or not; only its speed may differ.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "polygon/polygon_detail.h"
#include "swarf/polygon/polygon.h"

namespace swarf {
namespace {

Ring rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}
Ring reversed(Ring r) {
  std::reverse(r.begin(), r.end());
  return r;
}
Ring star(Vec2 c, double r0, double r1, int n, double phase) {
  Ring ring;
  for (int i = 0; i < 2 * n; ++i) {
    const double a = phase + kPi * i / n;
    const double r = i % 2 ? r1 : r0;
    ring.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return ring;
}

void expect_same_region(const PolygonSet& input) {
  const PolygonSet fast = detail::normalized_nonzero_fast(input);
  const PolygonSet ref = normalized(input, FillRule::kNonZero);
  EXPECT_NEAR(area(fast), area(ref), 1e-9);
  EXPECT_NEAR(perimeter(fast), perimeter(ref), 1e-6);
  // Orientation contract: outers CCW, holes CW; the non-zero region of the output is the
  // output itself (normalizing it again changes nothing).
  EXPECT_NEAR(area(normalized(fast)), area(fast), 1e-9);
  const Box2 b = bounds(ref).inflated(1.0);
  for (double x = b.min.x + 0.013; x < b.max.x; x += b.size().x / 13)
    for (double y = b.min.y + 0.017; y < b.max.y; y += b.size().y / 11)
      EXPECT_EQ(contains(fast, {x, y}), contains(ref, {x, y})) << x << ", " << y;
}

TEST(PolygonFast, ValidSetsPassThrough) {
  // Outer with a hole and an island in the hole.
  const PolygonSet s{{rect(0, 0, 10, 10), reversed(rect(2, 2, 8, 8)), rect(4, 4, 6, 6)}};
  expect_same_region(s);
  EXPECT_EQ(detail::normalized_nonzero_fast(s).rings.size(), 3u);
  expect_same_region({{star({0, 0}, 5, 2, 40, 0.1), star({20, 0}, 5, 2, 7, 0.3)}});
}

TEST(PolygonFast, InvalidSetsFallBackToTheUnion) {
  expect_same_region({{rect(0, 0, 4, 4), rect(2, 2, 6, 6)}});                // overlapping
  expect_same_region({{rect(0, 0, 4, 4), rect(4, 0, 8, 4)}});                // sharing an edge
  expect_same_region({{rect(0, 0, 4, 4), rect(4, 4, 8, 8)}});                // touching at a corner
  expect_same_region({{reversed(rect(0, 0, 4, 4))}});                        // clockwise alone
  expect_same_region({{rect(0, 0, 10, 10), rect(2, 2, 8, 8)}});              // nested, same way
  expect_same_region({{rect(0, 0, 10, 10), reversed(rect(2, 2, 12, 8))}});   // hole sticks out
  expect_same_region({{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}}});                  // bow-tie
  expect_same_region({{{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}}});          // vertex on an edge
  expect_same_region({{{{0, 0}, {4, 0}, {6, 0}, {4, 0}, {4, 4}, {0, 4}}}});  // spike
  expect_same_region({{{{0, 0}, {4, 0}, {2, 2}, {4, 4}, {0, 4}, {2, 2}}}});  // pinched
  expect_same_region({{rect(0, 0, 1, 1), rect(0, 0, 1, 1)}});                // duplicate
  expect_same_region({{rect(0, 0, 1e-6, 1e-6), rect(5, 5, 6, 6)}});          // below resolution
  expect_same_region({{rect(0, 0, 1e5, 1e5)}});  // beyond the fast range
}

TEST(PolygonFast, RandomPolygonsAgreeWithTheUnion) {
  std::mt19937 rng(20240601);
  std::uniform_real_distribution<double> u(-10, 10);
  for (int trial = 0; trial < 60; ++trial) {
    PolygonSet s;
    const int rings = 1 + trial % 4;
    for (int r = 0; r < rings; ++r) {
      if (trial % 3 == 0) {  // random, mostly self-intersecting
        Ring ring;
        for (int i = 0; i < 5 + trial % 7; ++i)
          ring.push_back({u(rng), u(rng)});
        s.rings.push_back(ring);
      } else {  // stars, sometimes overlapping, sometimes reversed
        Ring ring = star({u(rng), u(rng)}, 1 + std::abs(u(rng)) / 3, 0.5, 5 + trial % 9, u(rng));
        if (trial % 5 == 0) ring = reversed(ring);
        s.rings.push_back(ring);
      }
    }
    expect_same_region(s);
  }
}

// detail::clean_path replaces Clipper's CleanPolygon for speed and must give the same points
// in the same order (the slices, and every Boolean result, are cleaned with it). Rings on a
// small grid so that near-duplicates, fold-backs, spikes and collinear runs are common,
// plus rings that collapse entirely.
TEST(PolygonClean, SameAsClippersCleanPolygon) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(-6, 6), len(0, 14), kind(0, 3);
  int changed = 0, emptied = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    ClipperLib::Path ring;
    const int n = len(rng);
    ClipperLib::IntPoint p(coord(rng) * 3, coord(rng) * 3);
    for (int i = 0; i < n; ++i) {
      switch (kind(rng)) {
        case 0:  // a jump anywhere
          p = ClipperLib::IntPoint(coord(rng) * 3, coord(rng) * 3);
          break;
        case 1:  // a near-duplicate (within the 1.5 unit distance or just beyond)
          p = ClipperLib::IntPoint(p.X + coord(rng) / 3, p.Y + coord(rng) / 3);
          break;
        case 2:  // a step along a line (collinear runs, spikes when it turns back)
          p = ClipperLib::IntPoint(p.X + 2 * (trial % 5 - 2), p.Y + (trial % 3 - 1));
          break;
        default:  // back to the start (fold-backs, zero-area rings)
          if (!ring.empty()) p = ring.front();
          break;
      }
      ring.push_back(p);
    }
    ClipperLib::Path ours = ring, theirs;
    detail::clean_path(ours, 1.5);
    ClipperLib::CleanPolygon(ring, theirs, 1.5);
    ASSERT_EQ(ours, theirs) << "trial " << trial;
    changed += ours.size() != ring.size() ? 1 : 0;
    emptied += ring.size() >= 3 && ours.empty() ? 1 : 0;
  }
  // The cases above must actually occur, or the comparison proves little.
  EXPECT_GT(changed, 5000);
  EXPECT_GT(emptied, 500);
  // A long ring of real size (a sliced circle with duplicated and collinear points).
  ClipperLib::Path circle;
  for (int i = 0; i < 5000; ++i) {
    const double a = 2.0 * kPi * (i / 2) / 2500.0;
    circle.emplace_back(std::llround(4e6 * std::cos(a)), std::llround(4e6 * std::sin(a)));
  }
  ClipperLib::Path ours = circle, theirs;
  detail::clean_path(ours, 1.5);
  ClipperLib::CleanPolygon(circle, theirs, 1.5);
  EXPECT_EQ(ours, theirs);
  EXPECT_EQ(ours.size(), 2500u);
}

}  // namespace
}  // namespace swarf
