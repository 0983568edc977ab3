#include "swarf/dropcut/dropcut.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <utility>

namespace swarf {
namespace {

// A UV sphere built here so the test does not lean on the mesh generators it may later be
// compared against. Vertices lie on the sphere; facets are inside it by at most the sagitta.
Mesh uv_sphere(Vec3 c, double r, int seg) {
  Mesh m;
  const int rings = seg / 2;
  m.vertices.push_back(c + Vec3{0, 0, r});
  for (int i = 1; i < rings; ++i) {
    const double th = kPi * i / rings;
    for (int j = 0; j < seg; ++j) {
      const double ph = 2 * kPi * j / seg;
      m.vertices.push_back(c + Vec3{r * std::sin(th) * std::cos(ph),
                                    r * std::sin(th) * std::sin(ph), r * std::cos(th)});
    }
  }
  m.vertices.push_back(c + Vec3{0, 0, -r});
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>(1 + (i - 1) * seg + (j % seg)); };
  const auto south = static_cast<std::uint32_t>(m.vertices.size() - 1);
  for (int j = 0; j < seg; ++j)
    m.triangles.push_back({0, id(1, j), id(1, j + 1)});
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < seg; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  for (int j = 0; j < seg; ++j)
    m.triangles.push_back({id(rings - 1, j), south, id(rings - 1, j + 1)});
  return m;
}

Mesh box_mesh(Vec3 lo, Vec3 hi) {
  Mesh m;
  for (int k = 0; k < 8; ++k)
    m.vertices.push_back({(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z});
  const std::array<std::array<std::uint32_t, 4>, 6> faces{
      {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};
  for (const auto& f : faces) {
    m.triangles.push_back({f[0], f[1], f[2]});
    m.triangles.push_back({f[0], f[2], f[3]});
  }
  return m;
}

Mesh random_soup(int n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 20.0), z(-3.0, 3.0), d(-3.0, 3.0);
  Mesh m;
  for (int t = 0; t < n; ++t) {
    const Vec3 a{u(rng), u(rng), z(rng)};
    for (int k = 0; k < 3; ++k)
      m.vertices.push_back(k == 0 ? a : a + Vec3{d(rng), d(rng), d(rng)});
    const auto b = static_cast<std::uint32_t>(3 * t);
    m.triangles.push_back({b, b + 1, b + 2});
  }
  return m;
}

double height(const CutterShape& c, double d) {
  const double flat = c.radius_mm - c.corner_radius_mm;
  if (d <= flat) return 0.0;
  const double e = d - flat;
  return c.corner_radius_mm - std::sqrt(c.corner_radius_mm * c.corner_radius_mm - e * e);
}

// Independent truth for one triangle: the best of a dense barycentric sampling (a lower bound
// within the sampling's Lipschitz error of the exact maximum).
double sampled_drop(const Mesh& m, std::size_t t, const CutterShape& c, Vec2 p, int n) {
  double best = -std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double a = static_cast<double>(i) / n, b = static_cast<double>(j) / n;
      const Vec3 q = m.corner(t, 0) * (1 - a - b) + m.corner(t, 1) * a + m.corner(t, 2) * b;
      const double d = norm(q.xy() - p);
      if (d <= c.radius_mm) best = std::max(best, q.z - height(c, d));
    }
  return best;
}

const CutterShape kShapes[] = {{4.0, 4.0}, {3.0, 0.0}, {3.0, 1.0}};

TEST(DropCutter, IndexAgreesWithBruteForceOnRandomTriangles) {
  const Mesh soup = random_soup(400, 7);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-4.0, 24.0);
  for (const CutterShape& shape : kShapes) {
    auto dc = DropCutter::build(soup, shape);
    ASSERT_TRUE(dc.ok()) << dc.status().to_string();
    std::uniform_int_distribution<std::size_t> any(0, soup.size() + 5);
    for (int k = 0; k < 2000; ++k) {
      const Vec2 p{u(rng), u(rng)};
      const DropResult a = dc->drop(p), b = dc->drop_brute_force(p);
      ASSERT_EQ(a.hit(), b.hit());
      if (a.hit()) {
        ASSERT_EQ(a.tip_z, b.tip_z) << p.x << " " << p.y;
      }
      // A hint (any triangle, or none: an index past the end) changes nothing but the order.
      const DropResult h = dc->drop(p, any(rng));
      ASSERT_EQ(h.hit(), b.hit());
      if (h.hit()) {
        ASSERT_EQ(h.tip_z, b.tip_z) << p.x << " " << p.y;
      }
    }
  }
}

// The index lists a triangle in every cell its box overlaps and tests it in one of them (the
// one nearest the tool axis): with cells far smaller than the triangles (each spans dozens),
// at points on the cell lines and off them, the answer is still brute force's.
TEST(DropCutter, SmallCellsAndPointsOnCellLinesAgreeWithBruteForce) {
  const Mesh soup = random_soup(150, 5);
  for (const CutterShape& shape : kShapes) {
    DropCutterOptions o;
    o.cell_size_mm = 0.25;
    auto dc = DropCutter::build(soup, shape, o);
    ASSERT_TRUE(dc.ok()) << dc.status().to_string();
    EXPECT_GT(dc->index_entries(), 20 * soup.size());
    const double c = dc->cell_size_mm();
    std::size_t hits = 0;
    for (int i = 0; i < 60; ++i)
      for (int j = 0; j < 60; ++j) {
        // Every third point on a cell corner, the others inside cells.
        const double fx = (i % 3 == 0) ? 0.0 : 0.37, fy = (j % 3 == 0) ? 0.0 : 0.61;
        const Vec2 org = dc->mesh_bounds().xy().inflated(1e-9).min;  // the grid's origin
        const Vec2 p{org.x - 4.0 + (i * 2 + fx) * c, org.y - 4.0 + (j * 2 + fy) * c};
        const DropResult a = dc->drop(p), b = dc->drop_brute_force(p);
        ASSERT_EQ(a.hit(), b.hit()) << p.x << " " << p.y;
        if (a.hit()) {
          ASSERT_EQ(a.tip_z, b.tip_z) << p.x << " " << p.y;
          ++hits;
        }
      }
    EXPECT_GT(hits, 2000u);
  }
}

TEST(DropCutter, ContactFormulasMatchDenseSamplingOfEachTriangle) {
  const Mesh soup = random_soup(15, 3);
  std::mt19937 rng(5);
  for (const CutterShape& shape : kShapes) {
    for (std::size_t t = 0; t < soup.size(); ++t) {
      Mesh one;
      one.vertices = {soup.corner(t, 0), soup.corner(t, 1), soup.corner(t, 2)};
      one.triangles = {{0, 1, 2}};
      auto dc = DropCutter::build(one, shape);
      ASSERT_TRUE(dc.ok());
      const Vec3 c = (one.vertices[0] + one.vertices[1] + one.vertices[2]) / 3.0;
      std::uniform_real_distribution<double> u(-4.0, 4.0);
      for (int k = 0; k < 10; ++k) {
        const Vec2 p = c.xy() + Vec2{u(rng), u(rng)};
        const double exact = dc->drop_z(p);
        const double sampled = sampled_drop(one, 0, shape, p, 300);
        if (!std::isfinite(sampled)) continue;
        ASSERT_TRUE(std::isfinite(exact));
        // Exact is the maximum: never below the samples, and the samples come close.
        EXPECT_GE(exact, sampled - 1e-9);
        EXPECT_LE(exact - sampled, 0.06) << "shape R=" << shape.radius_mm;
      }
    }
  }
}

// Bull-nose against edges: the answer comes from Newton's method on the tip height along the
// edge, after a tangent bound that rejects edges. Truth here: a dense scan of each edge, then a
// ternary search around its best sample (another method, to 1e-13 along the edge). Vertical
// triangles hold the cutter on their edges and corners only, so their edges are what is tested;
// points are drawn so that the edges cross the corner torus, its rim and the flat bottom.
TEST(DropCutter, BullNoseEdgeContactMatchesAnIndependentSearch) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-6.0, 6.0), z(-2.0, 2.0);
  for (const CutterShape& shape : {CutterShape{3.0, 1.0}, CutterShape{5.0, 2.0},
                                   CutterShape{4.0, 3.9}, CutterShape{4.0, 0.05}}) {
    int hits = 0;
    for (int k = 0; k < 400; ++k) {
      // A vertical triangle: two points on top, one straight below the first.
      const Vec3 a{u(rng), u(rng), z(rng)}, b{u(rng), u(rng), z(rng)};
      Mesh tri;
      tri.vertices = {a, b, a - Vec3{0, 0, 5}};
      tri.triangles = {{0, 1, 2}};
      auto dc = DropCutter::build(tri, shape);
      ASSERT_TRUE(dc.ok());
      const Vec2 p{0.3 * u(rng), 0.3 * u(rng)};
      auto tip = [&](Vec3 q) {
        const double d = norm(q.xy() - p);
        return d <= shape.radius_mm ? q.z - height(shape, d)
                                    : -std::numeric_limits<double>::infinity();
      };
      double truth = -std::numeric_limits<double>::infinity();
      for (const auto& [s, e] :
           {std::pair{a, b}, std::pair{b, a - Vec3{0, 0, 5}}, std::pair{a - Vec3{0, 0, 5}, a}}) {
        constexpr int kN = 4000;
        int at = 0;
        double top = -std::numeric_limits<double>::infinity();
        for (int i = 0; i <= kN; ++i) {
          const double f = tip(s + (e - s) * (static_cast<double>(i) / kN));
          if (f > top) top = f, at = i;
        }
        if (!std::isfinite(top)) continue;
        double lo = std::max(0.0, (at - 1.0) / kN), hi = std::min(1.0, (at + 1.0) / kN);
        while (hi - lo > 1e-13) {
          const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
          if (tip(s + (e - s) * m1) < tip(s + (e - s) * m2))
            lo = m1;
          else
            hi = m2;
        }
        truth = std::max({truth, top, tip(s + (e - s) * lo)});
      }
      const DropResult got = dc->drop(p);
      ASSERT_EQ(got.hit(), std::isfinite(truth)) << k;
      if (!got.hit()) continue;
      ++hits;
      // Never above what the cutter can rest on, never below the search's best.
      EXPECT_GE(got.tip_z, truth - 1e-9) << k;
      EXPECT_LE(got.tip_z, truth + 1e-9) << k;
    }
    EXPECT_GT(hits, 150) << shape.radius_mm << " " << shape.corner_radius_mm;
  }
}

TEST(DropCutter, BallOnSphereMatchesClosedFormWithinTheSagitta) {
  const double Rs = 10.0, r = 4.0;
  const int seg = 96;
  const Vec3 c{1.0, -2.0, 3.0};
  auto dc = DropCutter::build(uv_sphere(c, Rs, seg), CutterShape{r, r});
  ASSERT_TRUE(dc.ok());
  // Facets lie inside the sphere by at most the sagitta of a cell's diagonal.
  const double sag = Rs * (1.0 - std::cos(kPi / seg * std::sqrt(2.0)));
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-13.0, 13.0);
  double worst = 0.0;
  for (int k = 0; k < 3000; ++k) {
    const Vec2 p{c.x + u(rng), c.y + u(rng)};
    const double d = norm(p - c.xy());
    if (d >= Rs + r - 0.2) continue;  // the faceted rim may fall out of reach
    const double expect = c.z + std::sqrt((Rs + r) * (Rs + r) - d * d) - r;
    const double got = dc->drop_z(p);
    ASSERT_LE(got, expect + 1e-9);
    // The vertical gap grows where the contact normal is steep: dz <= sag / cos(angle).
    const double cosang = std::sqrt(std::max(1e-6, 1.0 - d * d / ((Rs + r) * (Rs + r))));
    EXPECT_GE(got, expect - sag / cosang - 1e-9) << d;
    worst = std::max(worst, expect - got);
  }
  EXPECT_GT(worst, 0.0);  // the mesh is faceted: the closed form is not matched exactly
}

TEST(DropCutter, PlaneAndBoxEdgeClosedForms) {
  const Mesh box = box_mesh({0, 0, -5}, {10, 10, 5});
  for (const CutterShape& shape : kShapes) {
    auto dc = DropCutter::build(box, shape);
    ASSERT_TRUE(dc.ok());
    // On the top face.
    EXPECT_NEAR(dc->drop_z({5.0, 5.0}), 5.0, 1e-12);
    EXPECT_NEAR(dc->drop_z({0.5, 9.7}), 5.0, 1e-12);
    // Beside the edge x = 10: the tool rests on the edge with its profile at distance D.
    for (double D : {0.1, 0.5, 1.0, 2.0, 2.9}) {
      if (D >= shape.radius_mm) continue;
      const DropResult res = dc->drop({10.0 + D, 5.0});
      EXPECT_NEAR(res.tip_z, 5.0 - height(shape, D), 1e-9) << D;
    }
    // Beyond the reach of the tool, nothing.
    EXPECT_FALSE(dc->drop({10.0 + shape.radius_mm + 0.01, 5.0}).hit());
  }
  // A tilted plane (two triangles): ball rests at z = plane + r / cos(tilt) - r.
  Mesh plane;
  const double slope = 0.3;
  plane.vertices = {
      {-50, -50, -50 * slope}, {50, -50, 50 * slope}, {50, 50, 50 * slope}, {-50, 50, -50 * slope}};
  plane.triangles = {{0, 1, 2}, {0, 2, 3}};
  auto dc = DropCutter::build(plane, CutterShape{4.0, 4.0});
  ASSERT_TRUE(dc.ok());
  const double expect = 1.0 * slope + 4.0 * std::sqrt(1 + slope * slope) - 4.0;
  EXPECT_NEAR(dc->drop_z({1.0, 3.0}), expect, 1e-12);
  EXPECT_EQ(dc->drop({1.0, 3.0}).contact, ContactKind::kFacet);
}

// A tool whose axis lies exactly its radius from a vertical wall touches the wall's top edge
// with its rim (closed solids: touching counts), so it rests at top - corner radius. Grid
// points at whole distances from axis-aligned walls are common on real parts; the surface
// stress set (bench/surface_stress.sh, touching_cubes) found the ball edge contact lost there
// to rounding (B - A^2 computed as a difference of two large squares went a hair above R^2),
// so the CL fell to the floor, 1 mm to 4 mm below the tri-slice scan.
TEST(DropCutter, ToolExactlyItsRadiusFromAWallTouchesItsTopEdge) {
  const Mesh box = box_mesh({0, 0, 0}, {10, 20, 5});
  for (const CutterShape& shape : kShapes) {
    auto dc = DropCutter::build(box, shape);
    ASSERT_TRUE(dc.ok());
    const double R = shape.radius_mm;
    for (int k = 1; k < 200; ++k) {
      const double y = 0.1 * k - 0.003 * (k % 7);  // not on the edge ends
      if (y <= 0.0 || y >= 20.0) continue;
      for (const Vec2 p : {Vec2{10.0 + R, y}, Vec2{-R, y}}) {
        const DropResult res = dc->drop(p);
        ASSERT_TRUE(res.hit()) << "R " << R << " at " << p.x << ", " << p.y;
        EXPECT_NEAR(res.tip_z, 5.0 - shape.corner_radius_mm, 1e-9) << p.x << ", " << p.y;
      }
    }
  }
}

TEST(DropCutter, GridIsIndependentOfThreadCount) {
  const Mesh sphere = uv_sphere({0, 0, 0}, 8.0, 48);
  auto dc = DropCutter::build(sphere, CutterShape{3.0, 3.0});
  ASSERT_TRUE(dc.ok());
  ClGrid grid{{{-12, -12}, {12, 12}}, Axis::kX, 0.7, 0.3};
  Context one;
  one.threads = 1;
  Context many;
  many.threads = 4;
  auto a = drop_grid(*dc, grid, -100.0, one);
  auto b = drop_grid(*dc, grid, -100.0, many);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a->size(), b->size());
  for (std::size_t i = 0; i < a->size(); ++i)
    ASSERT_EQ((*a)[i], (*b)[i]);
  // Last line and last point sit on the region's far edges.
  EXPECT_DOUBLE_EQ(a->back().x, 12.0);
  EXPECT_DOUBLE_EQ(a->back().y, 12.0);
  EXPECT_FALSE(drop_grid(*dc, ClGrid{{{0, 0}, {1, 1}}, Axis::kX, 0.0, 0.1}, 0.0).ok());
}

}  // namespace
}  // namespace swarf
