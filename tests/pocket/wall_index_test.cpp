// The wall index answers exactly as the brute-force loops over every edge (geometry.h): the
// same doubles, bit for bit, on random queries in, on and around pockets with many edges.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pocket/geometry.h"
#include "pocket/wall_index.h"
#include "swarf/pocket/pocket_input.h"

namespace swarf::pocket {
namespace {

Ring circle(Vec2 c, double r, int n, bool clockwise) {
  Ring ring;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * kPi * k / n * (clockwise ? -1.0 : 1.0);
    ring.push_back(c + Vec2{std::cos(a), std::sin(a)} * r);
  }
  return ring;
}

// A plate with a dozen round bosses (580 edges), and a wavy outline with 3000 edges and two
// islands, one of them a long thin diagonal slot (edges crossing many cells).
std::vector<PolygonSet> pockets() {
  std::vector<PolygonSet> out;
  PolygonSet plate;
  plate.rings.push_back({{0, 0}, {100, 0}, {100, 80}, {0, 80}});
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j)
      plate.rings.push_back(circle({15.0 + 23 * i, 15.0 + 25 * j}, 2.0 + 0.7 * (i + j), 48, true));
  out.push_back(plate);
  PolygonSet wavy;
  Ring outer;
  for (int k = 0; k < 3000; ++k) {
    const double a = 2.0 * kPi * k / 3000;
    const double r = 50.0 + 4.0 * std::sin(17 * a);
    outer.push_back({r * std::cos(a), r * std::sin(a)});
  }
  wavy.rings.push_back(outer);
  wavy.rings.push_back(circle({10, -5}, 8.0, 200, true));
  wavy.rings.push_back({{-30, -20}, {-29, -21}, {20, 28}, {19, 29}});  // clockwise slot
  out.push_back(wavy);
  return out;
}

TEST(WallIndex, AnswersAsTheBruteForceLoops) {
  std::mt19937 rng(7);
  for (const PolygonSet& region : pockets()) {
    const WallIndex walls(region);
    ASSERT_TRUE(walls.indexed());
    Box2 box;
    for (const Ring& r : region.rings)
      for (Vec2 p : r)
        box.add(p);
    const Box2 around = box.inflated(20.0);
    std::uniform_real_distribution<double> ux(around.min.x, around.max.x),
        uy(around.min.y, around.max.y), len(0.0, 30.0), ang(0.0, 2.0 * kPi);
    std::vector<Vec2> points;
    for (int k = 0; k < 4000; ++k)
      points.push_back({ux(rng), uy(rng)});
    // On the walls: vertices and edge midpoints (ties between edges), and far away.
    for (const Ring& r : region.rings)
      for (std::size_t i = 0; i < r.size(); i += 7) {
        points.push_back(r[i]);
        points.push_back((r[i] + r[(i + 1) % r.size()]) * 0.5);
      }
    points.push_back({1e4, -3e3});
    int inside = 0;
    for (Vec2 p : points) {
      ASSERT_EQ(walls.distance(p), distance_to_rings(region, p)) << p.x << " " << p.y;
      const Vec2 n = walls.nearest(p), nb = nearest_on_rings(region, p);
      ASSERT_EQ(n.x, nb.x);
      ASSERT_EQ(n.y, nb.y);
      ASSERT_EQ(walls.inside(p), point_in_region(region, p)) << p.x << " " << p.y;
      inside += walls.inside(p);
      const Vec2 q = p + Vec2{std::cos(ang(rng)), std::sin(ang(rng))} * len(rng);
      ASSERT_EQ(walls.segment_distance(p, q), segment_distance_to_rings(region, p, q));
    }
    EXPECT_GT(inside, 1000);  // the queries cover both sides of the walls
    // A move round a boss's or island's side, pushed off it: the same points with the index
    // as with the plain loops.
    const WallIndex loops(region, false);
    ASSERT_FALSE(loops.indexed());
    int pushed = 0;
    for (int k = 0; k < 300; ++k) {
      const Vec2 a{ux(rng), uy(rng)}, b = a + Vec2{len(rng), len(rng)};
      std::vector<Vec2> v1, v2;
      keep_off_walls(walls, 3.0, 0.002, a, b, v1);
      keep_off_walls(loops, 3.0, 0.002, a, b, v2);
      pushed += v1.empty() ? 0 : 1;
      ASSERT_EQ(v1.size(), v2.size());
      for (std::size_t i = 0; i < v1.size(); ++i) {
        ASSERT_EQ(v1[i].x, v2[i].x);
        ASSERT_EQ(v1[i].y, v2[i].y);
      }
    }
    EXPECT_GT(pushed, 0);  // some moves do pass a wall's corner
  }
}

TEST(WallIndex, FewEdgesAreAnsweredByTheLoops) {
  PolygonSet square;
  square.rings.push_back({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  const WallIndex walls(square);
  EXPECT_FALSE(walls.indexed());
  EXPECT_EQ(walls.distance({2, 3}), 2.0);
  EXPECT_TRUE(walls.inside({2, 3}));
  EXPECT_FALSE(walls.inside({12, 3}));
}

}  // namespace
}  // namespace swarf::pocket
