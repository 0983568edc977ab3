#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "swarf/mesh/generate.h"
#include "swarf/mesh/mesh.h"
#include "swarf/mesh/slice.h"

namespace swarf {
namespace {

// Closed, consistently oriented, no degenerate triangles, positive volume.
void expect_clean_solid(const Mesh& m) {
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.closed()) << c.open_edges << " open, " << c.non_manifold_edges << " non-manifold";
  EXPECT_EQ(c.inconsistent_edges, 0u);
  EXPECT_EQ(c.degenerate_triangles, 0u);
  EXPECT_GT(c.volume_mm3, 0.0);
  // Euler characteristic of a closed 2-manifold: V - E + F = 2 - 2g, with E = 3F/2.
}

int euler_characteristic(const Mesh& m) {
  return static_cast<int>(m.vertices.size()) - static_cast<int>(3 * m.size() / 2) +
         static_cast<int>(m.size());
}

TEST(Mesh, WeldMergesExactlyEqualCoordinatesInFirstAppearanceOrder) {
  const std::vector<std::array<Vec3, 3>> soup{
      {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
      {{{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}},
      {{{-0.0, 0, 0}, {0, 1, 1e-300}, {1, 1, 0}}},  // -0 welds with 0; 1e-300 does not with 0
  };
  const Mesh m = weld(soup);
  ASSERT_EQ(m.vertices.size(), 5u);
  EXPECT_EQ(m.vertices[0], (Vec3{0, 0, 0}));
  EXPECT_EQ(m.vertices[1], (Vec3{1, 0, 0}));
  EXPECT_EQ(m.vertices[2], (Vec3{0, 1, 0}));
  EXPECT_EQ(m.vertices[3], (Vec3{1, 1, 0}));
  EXPECT_EQ(m.vertices[4], (Vec3{0, 1, 1e-300}));
  EXPECT_EQ(m.triangles[1], (std::array<std::uint32_t, 3>{1, 3, 2}));
  EXPECT_EQ(m.triangles[2], (std::array<std::uint32_t, 3>{0, 4, 3}));
  EXPECT_FALSE(std::signbit(m.vertices[0].x));
}

TEST(Mesh, CheckFindsOpenNonManifoldInconsistentAndDegenerate) {
  const Mesh box = make_box({{0, 0, 0}, {1, 2, 3}});
  MeshCheck c = check_mesh(box);
  EXPECT_TRUE(c.closed());
  EXPECT_EQ(c.triangles, 12u);
  EXPECT_DOUBLE_EQ(c.volume_mm3, 6.0);

  Mesh open = box;
  open.triangles.pop_back();
  c = check_mesh(open);
  EXPECT_EQ(c.open_edges, 3u);
  EXPECT_FALSE(c.closed());

  Mesh flipped = box;
  std::swap(flipped.triangles[0][0], flipped.triangles[0][1]);
  c = check_mesh(flipped);
  EXPECT_TRUE(c.closed());
  EXPECT_EQ(c.inconsistent_edges, 3u);

  Mesh inside_out = box;
  for (auto& t : inside_out.triangles)
    std::swap(t[1], t[2]);
  EXPECT_DOUBLE_EQ(check_mesh(inside_out).volume_mm3, -6.0);
  EXPECT_EQ(check_mesh(inside_out).inconsistent_edges, 0u);

  Mesh fin = box;  // a third triangle on an existing edge
  fin.vertices.push_back({0.5, -1, 0});
  fin.triangles.push_back({0, 1, static_cast<std::uint32_t>(fin.vertices.size() - 1)});
  c = check_mesh(fin);
  EXPECT_EQ(c.non_manifold_edges, 1u);
  EXPECT_FALSE(c.closed());

  Mesh degenerate = box;
  degenerate.vertices.push_back({0.5, 0, 0});  // on the edge (0,0,0)-(1,0,0)
  degenerate.triangles.push_back(
      {0, 1, static_cast<std::uint32_t>(degenerate.vertices.size() - 1)});
  degenerate.triangles.push_back({0, 0, 1});
  EXPECT_EQ(check_mesh(degenerate).degenerate_triangles, 2u);
}

TEST(Mesh, TransformedRotatesAboutZThenTranslates) {
  const Mesh box = make_box({{1, 0, 0}, {3, 1, 1}});
  const Mesh t = transformed(box, 90.0, {10, 0, 5});
  const Box3 b = bounds(t);
  // (x, y) -> (-y, x): x in [1,3], y in [0,1] -> x' in [-1,0], y' in [1,3]; then shifted.
  EXPECT_EQ(b.min, (Vec3{9, 1, 5}));
  EXPECT_EQ(b.max, (Vec3{10, 3, 6}));
  EXPECT_DOUBLE_EQ(check_mesh(t).volume_mm3, 2.0);
  const Mesh r = transformed(box, 30.0);
  EXPECT_NEAR(check_mesh(r).volume_mm3, 2.0, 1e-12);
  EXPECT_NEAR(r.vertices[1].x, 3 * std::cos(deg_to_rad(30)), 1e-12);
}

// Two closed shells appended stay two closed shells: edges, orientation and volume add up.
TEST(Mesh, AppendKeepsBothShellsIntact) {
  Mesh m = make_box({{0, 0, 0}, {2, 3, 4}});
  const Mesh b = make_box({{10, 0, 0}, {11, 1, 1}});
  append(m, b);
  EXPECT_EQ(m.vertices.size(), 16u);
  EXPECT_EQ(m.triangles.size(), 24u);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.closed());
  EXPECT_EQ(c.inconsistent_edges, 0u);
  EXPECT_NEAR(c.volume_mm3, 24.0 + 1.0, 1e-12);
  EXPECT_EQ(bounds(m).max.x, 11.0);
}

TEST(Generate, BoxIsExact) {
  const Mesh m = make_box({{-1, -2, -3}, {4, 5, 6}});
  expect_clean_solid(m);
  EXPECT_DOUBLE_EQ(check_mesh(m).volume_mm3, 5.0 * 7.0 * 9.0);
  EXPECT_EQ(euler_characteristic(m), 2);
  EXPECT_EQ(bounds(m).min, (Vec3{-1, -2, -3}));
}

TEST(Generate, CylinderIsPolygonalPrism) {
  const int n = 40;
  const double r = 3.0, h = 7.0;
  const Mesh m = make_cylinder({1, 2, -1}, r, h, n);
  expect_clean_solid(m);
  EXPECT_EQ(euler_characteristic(m), 2);
  EXPECT_NEAR(check_mesh(m).volume_mm3, 0.5 * n * r * r * std::sin(2 * kPi / n) * h, 1e-9);
  const Box3 b = bounds(m);
  EXPECT_DOUBLE_EQ(b.min.z, -1.0);
  EXPECT_DOUBLE_EQ(b.max.z, 6.0);
  EXPECT_DOUBLE_EQ(b.max.x, 4.0);
}

TEST(Generate, SphereVolumeConverges) {
  const double r = 5.0;
  double prev_err = 1e9;
  for (int n : {16, 32, 64, 128}) {
    const Mesh m = make_sphere({0, 0, 1}, r, n);
    expect_clean_solid(m);
    EXPECT_EQ(euler_characteristic(m), 2);
    const double err = std::abs(check_mesh(m).volume_mm3 - 4.0 / 3.0 * kPi * r * r * r);
    EXPECT_LT(err, prev_err / 3.0);  // second order: error falls ~4x per doubling
    prev_err = err;
  }
  // An inscribed polyhedron: every vertex on the sphere, volume below the sphere's.
  const Mesh m = make_sphere({0, 0, 1}, r, 64);
  for (const Vec3& v : m.vertices)
    EXPECT_NEAR(distance(v, {0, 0, 1}), r, 1e-12);
  EXPECT_LT(check_mesh(m).volume_mm3, 4.0 / 3.0 * kPi * r * r * r);
  EXPECT_LT(prev_err / (4.0 / 3.0 * kPi * r * r * r), 2e-3);
}

TEST(Generate, TorusVolumeAndGenus) {
  const double R = 20.0, r = 5.0;
  const Mesh m = make_torus({0, 0, 0}, R, r, 192, 96);
  expect_clean_solid(m);
  EXPECT_EQ(euler_characteristic(m), 0);  // genus 1
  // Pappus: 2 pi R * pi r^2, approached from below by the inscribed polyhedron.
  const double exact = 2 * kPi * R * kPi * r * r;
  const double v = check_mesh(m).volume_mm3;
  EXPECT_LT(v, exact);
  EXPECT_NEAR(v, exact, exact * 2e-3);
}

TEST(Generate, BlockWithBosses) {
  const Vec3 size{500, 500, 100};
  const Mesh m = make_block_with_bosses(size, 80, 30);
  expect_clean_solid(m);
  EXPECT_EQ(euler_characteristic(m), 2);
  EXPECT_DOUBLE_EQ(check_mesh(m).volume_mm3, 500.0 * 500 * 100 + 4 * 80.0 * 80 * 30);
  EXPECT_EQ(bounds(m).max, (Vec3{500, 500, 130}));
  // A slice through the bosses: four 80 x 80 squares centred on the quarter points.
  const auto s = slice_mesh(m, Axis::kZ, {115.0});
  ASSERT_EQ(s[0].rings.size(), 4u);
  EXPECT_NEAR(area(s[0]), 4 * 80.0 * 80, 1e-6);
  EXPECT_TRUE(contains(s[0], {125, 375}));
  EXPECT_FALSE(contains(s[0], {250, 250}));
}

// Pappus volume of the filleted part, from an independent description of its profile region
// in the (rho, z) half-plane: the tube disk, plus for each fillet the web between the plate,
// the tube and the fillet circle (points above the plate, between the fillet centre and the
// tube axis circle, below the line through the two centres, outside the fillet circle).
// Integrated column by column: each column is a union of at most three z intervals.
double filleted_part_volume(const FilletedTorusPart& p) {
  const double R = p.major_radius, r = p.minor_radius;
  auto column = [&](double rho) {
    std::vector<std::pair<double, double>> iv;
    if (std::abs(rho - R) <= r) {
      const double s = std::sqrt(r * r - (rho - R) * (rho - R));
      iv.push_back({r - s, r + s});
    }
    for (const auto& [f, sign] :
         {std::pair{p.inner_fillet, -1.0}, std::pair{p.outer_fillet, 1.0}}) {
      const double cx = R + sign * 2 * std::sqrt(r * f);
      if (rho < std::min(cx, R) || rho > std::max(cx, R)) continue;
      const double line = f + (r - f) * (rho - cx) / (R - cx);  // through (cx, f) and (R, r)
      const double dx = rho - cx;
      const double q = std::abs(dx) <= f ? std::sqrt(f * f - dx * dx) : -1.0;
      if (q < 0) {
        iv.push_back({0.0, line});
      } else {
        iv.push_back({0.0, std::min(line, f - q)});
        if (f + q < line) iv.push_back({f + q, line});
      }
    }
    std::sort(iv.begin(), iv.end());
    double len = 0, end = -1e300;
    for (auto [lo, hi] : iv) {
      lo = std::max(lo, end);
      if (hi > lo) {
        len += hi - lo;
        end = hi;
      }
    }
    return len;
  };
  const int n = 200000;
  const double b = p.plate_size / 2;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double rho = b * (i + 0.5) / n;
    sum += 2 * kPi * rho * column(rho);
  }
  return sum * b / n + p.plate_size * p.plate_size * p.plate_thickness;
}

TEST(Generate, FilletedTorusPartIsClosedAndMatchesItsProfile) {
  const FilletedTorusPart p;  // seed 001 Fig. 11 defaults: fillets 4 mm outside, 3 mm inside
  const Mesh m = make_filleted_torus_part(p);
  expect_clean_solid(m);
  EXPECT_EQ(euler_characteristic(m), 2);
  const Box3 b = bounds(m);
  EXPECT_DOUBLE_EQ(b.min.x, -40.0);
  EXPECT_DOUBLE_EQ(b.max.y, 40.0);
  EXPECT_DOUBLE_EQ(b.min.z, -10.0);
  EXPECT_NEAR(b.max.z, 2 * p.minor_radius, 1e-3);
  const double exact = filleted_part_volume(p);
  EXPECT_NEAR(check_mesh(m).volume_mm3, exact, exact * 1e-3);

  // Slices: at the tube centre height the section is the annulus R -+ r (4 pi R r), and
  // just above the plate the fillets widen the ring to R - 2 sqrt(r fi) .. R + 2 sqrt(r fo).
  const double R = p.major_radius, r = p.minor_radius;
  const auto s = slice_mesh(m, Axis::kZ, {r, 1e-9, -5.0});
  EXPECT_NEAR(area(s[0]), 4 * kPi * R * r, 4 * kPi * R * r * 2e-3);
  EXPECT_EQ(s[0].rings.size(), 2u);
  const double ri = R - 2 * std::sqrt(r * p.inner_fillet),
               ro = R + 2 * std::sqrt(r * p.outer_fillet);
  EXPECT_NEAR(area(s[1]), kPi * (ro * ro - ri * ri), kPi * (ro * ro - ri * ri) * 2e-3);
  EXPECT_DOUBLE_EQ(area(s[2]), 80.0 * 80.0);
}

TEST(Generate, FilletedTorusPartProfileIsTangentContinuous) {
  // The fillets are tangent to the plate and to the tube, so the radial section (plane
  // y = 0) turns smoothly everywhere except at the four plate corners: the turn at each
  // vertex is at most about one profile step (2 pi / segments), where a fillet placed
  // wrongly would leave a kink of many degrees.
  FilletedTorusPart p;
  p.segments = 256;
  const Mesh m = make_filleted_torus_part(p);
  const auto s = slice_mesh(m, Axis::kY, {0.0});
  ASSERT_EQ(s[0].rings.size(), 1u);
  const Ring& ring = s[0].rings[0];
  const double step = 2 * kPi / p.segments;
  double max_turn = 0.0;
  int fillet_points = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i],
               c = ring[(i + 1) % ring.size()];
    const Vec3 q = from_plane(b, 0.0, Axis::kY);
    if (std::abs(std::abs(q.x) - 40.0) < 1e-9) continue;  // plate corners
    const double turn = std::abs(std::atan2(cross(b - a, c - b), dot(b - a, c - b)));
    max_turn = std::max(max_turn, turn);
    if (q.z > 1e-6 && q.z < 3.0) ++fillet_points;
  }
  EXPECT_LT(max_turn, 1.5 * step);
  EXPECT_GT(fillet_points, 20);
}

}  // namespace
}  // namespace swarf
